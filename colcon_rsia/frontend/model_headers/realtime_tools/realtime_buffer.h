// colcon-rsia model of <realtime_tools/realtime_buffer.h> (ROS 1, and the
// Humble name of the ROS 2 header): the lock-free hand-over of a value from a
// non-real-time thread (a subscription callback) to a real-time loop (a
// controller's update). It publishes nothing; it is modelled so that code
// using it parses, and so that `*buffer.readFromRT()` has the stored type.
#ifndef RSIA_MODEL_REALTIME_TOOLS_REALTIME_BUFFER
#define RSIA_MODEL_REALTIME_TOOLS_REALTIME_BUFFER

namespace realtime_tools
{

template <class T>
class RealtimeBuffer
{
public:
  RealtimeBuffer();
  explicit RealtimeBuffer(const T& data);
  RealtimeBuffer(const RealtimeBuffer& source);
  ~RealtimeBuffer();
  RealtimeBuffer& operator=(const RealtimeBuffer& source);

  T* readFromRT();
  T* readFromNonRT() const;
  void writeFromNonRT(const T& data);
  void initRT(const T& data);
  void reset();
};

}  // namespace realtime_tools

#endif  // RSIA_MODEL_REALTIME_TOOLS_REALTIME_BUFFER
