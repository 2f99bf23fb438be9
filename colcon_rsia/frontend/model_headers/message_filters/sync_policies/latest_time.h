// colcon-rsia model of <message_filters/sync_policies/latest_time.h> (ROS 2 Humble name)
#include <message_filters/sync_policies/latest_time.hpp>
