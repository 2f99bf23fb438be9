// colcon-rsia model of <ros/datatypes.h>.
#include <ros/types.h>
