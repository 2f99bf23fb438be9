// colcon-rsia model of <ros/assert.h>: ROS_ASSERT and friends, enabled unless
// NDEBUG (the condition runs inside a do-while; the message is a ROS_FATAL in
// the failing branch).
#ifndef RSIA_MODEL_ROS_ASSERT_H
#define RSIA_MODEL_ROS_ASSERT_H

#include <cstdlib>

#include <ros/console.h>
#include <ros/static_assert.h>

#define ROS_ISSUE_BREAK() abort();

#ifndef NDEBUG
#ifndef ROS_ASSERT_ENABLED
#define ROS_ASSERT_ENABLED
#endif
#endif

#ifdef ROS_ASSERT_ENABLED
#define ROS_BREAK()                                    \
  do                                                   \
  {                                                    \
    ROS_FATAL("breakpoint at %s:%d", __FILE__, __LINE__); \
    ROS_ISSUE_BREAK()                                  \
  } while (false)

#define ROS_ASSERT(cond)                                                 \
  do                                                                     \
  {                                                                      \
    if (!(cond))                                                         \
    {                                                                    \
      ROS_FATAL("assertion failed at %s:%d: %s", __FILE__, __LINE__, #cond); \
      ROS_ISSUE_BREAK()                                                  \
    }                                                                    \
  } while (false)

#define ROS_ASSERT_MSG(cond, ...)                                        \
  do                                                                     \
  {                                                                      \
    if (!(cond))                                                         \
    {                                                                    \
      ROS_FATAL("assertion failed at %s:%d: %s: ", __FILE__, __LINE__, #cond); \
      ROS_FATAL(__VA_ARGS__);                                            \
      ROS_FATAL("\n");                                                   \
      ROS_ISSUE_BREAK();                                                 \
    }                                                                    \
  } while (false)

#define ROS_ASSERT_CMD(cond, cmd) \
  do                              \
  {                               \
    if (!(cond))                  \
    {                             \
      cmd;                        \
    }                             \
  } while (false)
#else
#define ROS_BREAK()
#define ROS_ASSERT(cond)
#define ROS_ASSERT_MSG(cond, ...)
#define ROS_ASSERT_CMD(cond, cmd)
#endif

#endif  // RSIA_MODEL_ROS_ASSERT_H
