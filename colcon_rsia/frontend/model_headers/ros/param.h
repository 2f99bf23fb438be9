// colcon-rsia model of <ros/param.h>: the ros::param free functions.
#ifndef RSIA_MODEL_ROS_PARAM_H
#define RSIA_MODEL_ROS_PARAM_H

#include <map>
#include <string>
#include <vector>

#include <ros/forwards.h>
#include <xmlrpcpp/XmlRpcValue.h>

namespace ros
{

namespace param
{

void set(const std::string& key, const XmlRpc::XmlRpcValue& v);
void set(const std::string& key, const std::string& s);
void set(const std::string& key, const char* s);
void set(const std::string& key, double d);
void set(const std::string& key, int i);
void set(const std::string& key, bool b);
void set(const std::string& key, const std::vector<std::string>& vec);
void set(const std::string& key, const std::vector<double>& vec);
void set(const std::string& key, const std::vector<float>& vec);
void set(const std::string& key, const std::vector<int>& vec);
void set(const std::string& key, const std::vector<bool>& vec);
void set(const std::string& key, const std::map<std::string, std::string>& map);
void set(const std::string& key, const std::map<std::string, double>& map);
void set(const std::string& key, const std::map<std::string, float>& map);
void set(const std::string& key, const std::map<std::string, int>& map);
void set(const std::string& key, const std::map<std::string, bool>& map);

bool get(const std::string& key, std::string& s);
bool get(const std::string& key, double& d);
bool get(const std::string& key, float& f);
bool get(const std::string& key, int& i);
bool get(const std::string& key, bool& b);
bool get(const std::string& key, XmlRpc::XmlRpcValue& v);
bool get(const std::string& key, std::vector<std::string>& vec);
bool get(const std::string& key, std::vector<double>& vec);
bool get(const std::string& key, std::vector<float>& vec);
bool get(const std::string& key, std::vector<int>& vec);
bool get(const std::string& key, std::vector<bool>& vec);
bool get(const std::string& key, std::map<std::string, std::string>& map);
bool get(const std::string& key, std::map<std::string, double>& map);
bool get(const std::string& key, std::map<std::string, float>& map);
bool get(const std::string& key, std::map<std::string, int>& map);
bool get(const std::string& key, std::map<std::string, bool>& map);

bool getCached(const std::string& key, std::string& s);
bool getCached(const std::string& key, double& d);
bool getCached(const std::string& key, float& f);
bool getCached(const std::string& key, int& i);
bool getCached(const std::string& key, bool& b);
bool getCached(const std::string& key, XmlRpc::XmlRpcValue& v);
bool getCached(const std::string& key, std::vector<std::string>& vec);
bool getCached(const std::string& key, std::vector<double>& vec);
bool getCached(const std::string& key, std::vector<float>& vec);
bool getCached(const std::string& key, std::vector<int>& vec);
bool getCached(const std::string& key, std::vector<bool>& vec);
bool getCached(const std::string& key, std::map<std::string, std::string>& map);
bool getCached(const std::string& key, std::map<std::string, double>& map);
bool getCached(const std::string& key, std::map<std::string, float>& map);
bool getCached(const std::string& key, std::map<std::string, int>& map);
bool getCached(const std::string& key, std::map<std::string, bool>& map);

bool has(const std::string& key);
bool del(const std::string& key);
bool search(const std::string& key, std::string& result);
bool search(const std::string& ns, const std::string& key, std::string& result);
bool getParamNames(std::vector<std::string>& keys);

template <typename T>
bool param(const std::string& param_name, T& param_val, const T& default_val);
template <typename T>
T param(const std::string& param_name, const T& default_val);

}  // namespace param

}  // namespace ros

#endif  // RSIA_MODEL_ROS_PARAM_H
