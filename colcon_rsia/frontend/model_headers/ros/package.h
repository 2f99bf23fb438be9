// colcon-rsia model of <ros/package.h> (roslib).
#ifndef RSIA_MODEL_ROS_PACKAGE_H
#define RSIA_MODEL_ROS_PACKAGE_H

#include <map>
#include <string>
#include <vector>

namespace ros
{

namespace package
{

typedef std::vector<std::string> V_string;
typedef std::map<std::string, std::string> M_string;

std::string command(const std::string& cmd);
void command(const std::string& cmd, V_string& output);
std::string getPath(const std::string& package_name);
bool getAll(V_string& packages);
void getPlugins(const std::string& package, const std::string& attribute, V_string& plugins,
                bool force_recrawl = false);
void getPlugins(const std::string& package, const std::string& attribute, M_string& plugins,
                bool force_recrawl = false);

}  // namespace package

}  // namespace ros

#endif  // RSIA_MODEL_ROS_PACKAGE_H
