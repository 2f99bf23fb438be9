// colcon-rsia model of <message_filters/message_event.h> (ROS 2 Humble name)
#include <message_filters/message_event.hpp>
