// colcon-rsia model of <ros/types.h> and the container typedefs of
// <ros/datatypes.h>.
#ifndef RSIA_MODEL_ROS_TYPES_H
#define RSIA_MODEL_ROS_TYPES_H

#include <cstdint>
#include <list>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <boost/shared_ptr.hpp>

namespace ros
{

typedef std::vector<std::pair<std::string, std::string>> VP_string;
typedef std::vector<std::string> V_string;
typedef std::set<std::string> S_string;
typedef std::map<std::string, std::string> M_string;
typedef std::pair<std::string, std::string> StringPair;
typedef boost::shared_ptr<M_string> M_stringPtr;

}  // namespace ros

#endif  // RSIA_MODEL_ROS_TYPES_H
