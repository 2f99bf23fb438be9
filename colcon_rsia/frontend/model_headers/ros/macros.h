// colcon-rsia model of <ros/macros.h>.
#ifndef RSIA_MODEL_ROS_MACROS_H
#define RSIA_MODEL_ROS_MACROS_H

#define ROS_DEPRECATED __attribute__((deprecated))
#define ROS_FORCE_INLINE __attribute__((always_inline))
#define ROS_HELPER_IMPORT
#define ROS_HELPER_EXPORT
#define ROS_HELPER_LOCAL
#define ROSCPP_DECL
#define ROSCPP_SERIALIZATION_DECL
#define ROSTIME_DECL
#define ROSCONSOLE_DECL
#define XMLRPCPP_DECL

#endif  // RSIA_MODEL_ROS_MACROS_H
