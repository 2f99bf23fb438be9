// colcon-rsia model of <ros/static_assert.h>.
#ifndef RSIA_MODEL_ROS_STATIC_ASSERT_H
#define RSIA_MODEL_ROS_STATIC_ASSERT_H

#define ROS_COMPILE_ASSERT(cond) static_assert(cond, #cond)
#define ROS_STATIC_ASSERT(cond) static_assert(cond, #cond)
#define ROS_STATIC_ASSERT_MSG(cond, msg) static_assert(cond, msg)

#endif  // RSIA_MODEL_ROS_STATIC_ASSERT_H
