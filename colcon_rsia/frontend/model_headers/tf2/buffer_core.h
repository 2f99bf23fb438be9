// colcon-rsia model of <tf2/buffer_core.h>: tf2::BufferCore.
#ifndef RSIA_MODEL_TF2_BUFFER_CORE_H
#define RSIA_MODEL_TF2_BUFFER_CORE_H

#include <string>
#include <vector>

#include <boost/function.hpp>
#include <geometry_msgs/TransformStamped.h>
#include <ros/duration.h>
#include <ros/time.h>
#include <tf2/exceptions.h>
#include <tf2/transform_datatypes.h>

namespace tf2
{

typedef uint32_t CompactFrameID;
typedef uint64_t TransformableRequestHandle;

enum TransformableResult
{
  TransformAvailable,
  TransformFailure,
};

class BufferCore
{
public:
  static const int DEFAULT_CACHE_TIME = 10;
  static const uint32_t MAX_GRAPH_DEPTH = 1000UL;

  BufferCore(ros::Duration cache_time_ = ros::Duration(DEFAULT_CACHE_TIME));
  virtual ~BufferCore(void);

  void clear();
  bool setTransform(const geometry_msgs::TransformStamped& transform, const std::string& authority,
                    bool is_static = false);
  geometry_msgs::TransformStamped lookupTransform(const std::string& target_frame,
                                                  const std::string& source_frame,
                                                  const ros::Time& time) const;
  geometry_msgs::TransformStamped lookupTransform(const std::string& target_frame,
                                                  const ros::Time& target_time,
                                                  const std::string& source_frame,
                                                  const ros::Time& source_time,
                                                  const std::string& fixed_frame) const;
  bool canTransform(const std::string& target_frame, const std::string& source_frame, const ros::Time& time,
                    std::string* error_msg = NULL) const;
  bool canTransform(const std::string& target_frame, const ros::Time& target_time,
                    const std::string& source_frame, const ros::Time& source_time,
                    const std::string& fixed_frame, std::string* error_msg = NULL) const;
  std::string allFramesAsYAML(double current_time) const;
  std::string allFramesAsYAML() const;
  std::string allFramesAsString() const;
  bool _frameExists(const std::string& frame_id_str) const;
  bool _getParent(const std::string& frame_id, ros::Time time, std::string& parent) const;
  void _getFrameStrings(std::vector<std::string>& ids) const;
  ros::Duration getCacheLength();
  bool isUsingDedicatedThread() const;
  void setUsingDedicatedThread(bool value);
};

}  // namespace tf2

#endif  // RSIA_MODEL_TF2_BUFFER_CORE_H
