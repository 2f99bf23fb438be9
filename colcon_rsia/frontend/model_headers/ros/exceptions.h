// colcon-rsia model of <ros/exceptions.h>.
#ifndef RSIA_MODEL_ROS_EXCEPTIONS_H
#define RSIA_MODEL_ROS_EXCEPTIONS_H

#include <ros/exception.h>

namespace ros
{

class InvalidNodeNameException : public ros::Exception
{
public:
  InvalidNodeNameException(const std::string& name, const std::string& reason);
};

class InvalidNameException : public ros::Exception
{
public:
  InvalidNameException(const std::string& msg);
};

class ConflictingSubscriptionException : public ros::Exception
{
public:
  ConflictingSubscriptionException(const std::string& msg);
};

class InvalidParameterException : public ros::Exception
{
public:
  InvalidParameterException(const std::string& msg);
};

class InvalidPortException : public ros::Exception
{
public:
  InvalidPortException(const std::string& msg);
};

}  // namespace ros

#endif  // RSIA_MODEL_ROS_EXCEPTIONS_H
