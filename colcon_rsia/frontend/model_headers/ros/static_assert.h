// colcon-rsia model of <ros/static_assert.h>. The model cannot know the
// values real code asserts on (a message's checksum, a type's size): its
// assertions check nothing, so that a condition the real headers meet
// does not stop the parse.
#ifndef RSIA_MODEL_ROS_STATIC_ASSERT_H
#define RSIA_MODEL_ROS_STATIC_ASSERT_H

#define ROS_COMPILE_ASSERT(cond) static_assert(true, "")
#define ROS_STATIC_ASSERT(cond) static_assert(true, "")
#define ROS_STATIC_ASSERT_MSG(cond, msg) static_assert(true, "")

#endif  // RSIA_MODEL_ROS_STATIC_ASSERT_H
