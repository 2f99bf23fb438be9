// colcon-rsia partial model of Gazebo classic (gazebo 9-11), the simulator
// gazebo_ros_pkgs' plugins run in. Only what decides the facts: the plugin
// base classes, their registration macros and the world events whose
// callbacks gzserver calls on every simulation step (gazebo/common/Plugin.hh,
// gazebo/common/Events.hh). Everything else of `gazebo::` is left to the
// stand-ins of unknown libraries: the stand-in of every <gazebo/...> include
// includes this header before them, and each name declared here sets the
// macro (RSIA_REPAIRED__<qualified name>) that makes them and the repairs
// skip it.
#ifndef RSIA_MODEL_PARTIAL_GAZEBO_H
#define RSIA_MODEL_PARTIAL_GAZEBO_H

#include <memory>

#include <rsia_model/message.h>

// a class of an unknown library, made from anything (as the stand-ins'
// catch-all classes are)
#define RSIA_MODEL_GAZEBO_CATCH_ALL_(name)                      \
  struct name : ::rsia_model::Unknown                           \
  {                                                             \
    using ::rsia_model::Unknown::Unknown;                       \
    name() = default;                                           \
    name(const ::rsia_model::Unknown&);                         \
    template <class RsiaV>                                      \
    name& operator=(RsiaV&&);                                   \
    using Ptr = ::rsia_model::UnknownPointer<name>;             \
    using ConstPtr = ::rsia_model::UnknownPointer<const name>;  \
    using SharedPtr = Ptr;                                      \
    using ConstSharedPtr = ConstPtr;                            \
  };

// sdf (Gazebo's headers include it): what a plugin's Load() receives,
// unless the stand-in of an <sdf/...> include declared it already
#ifndef RSIA_MODEL_UNKNOWN_sdf_H
namespace sdf
{
#ifndef RSIA_REPAIRED__sdf__Element
#define RSIA_REPAIRED__sdf__Element 1
RSIA_MODEL_GAZEBO_CATCH_ALL_(Element)
#endif
#ifndef RSIA_REPAIRED__sdf__ElementPtr
#define RSIA_REPAIRED__sdf__ElementPtr 1
typedef ::rsia_model::UnknownPointer<Element> ElementPtr;
#endif
}  // namespace sdf
#endif

namespace gazebo
{

// the plugin types gzserver loads; Load(entity, sdf) is left out, its
// parameter types being the unknown library's
#ifndef RSIA_REPAIRED__gazebo__ModelPlugin
#define RSIA_REPAIRED__gazebo__ModelPlugin 1
class ModelPlugin
{
public:
  virtual ~ModelPlugin() = default;
  virtual void Init() {}
  virtual void Reset() {}
};
#endif
#ifndef RSIA_REPAIRED__gazebo__SensorPlugin
#define RSIA_REPAIRED__gazebo__SensorPlugin 1
class SensorPlugin
{
public:
  virtual ~SensorPlugin() = default;
  virtual void Init() {}
  virtual void Reset() {}
};
#endif
#ifndef RSIA_REPAIRED__gazebo__WorldPlugin
#define RSIA_REPAIRED__gazebo__WorldPlugin 1
class WorldPlugin
{
public:
  virtual ~WorldPlugin() = default;
  virtual void Init() {}
  virtual void Reset() {}
};
#endif
#ifndef RSIA_REPAIRED__gazebo__SystemPlugin
#define RSIA_REPAIRED__gazebo__SystemPlugin 1
class SystemPlugin
{
public:
  virtual ~SystemPlugin() = default;
  virtual void Init() {}
  virtual void Reset() {}
};
#endif

namespace event
{

#ifndef RSIA_REPAIRED__gazebo__event__Connection
#define RSIA_REPAIRED__gazebo__event__Connection 1
class Connection
{
public:
  int Id() const;
};
#endif
#ifndef RSIA_REPAIRED__gazebo__event__ConnectionPtr
#define RSIA_REPAIRED__gazebo__event__ConnectionPtr 1
typedef std::shared_ptr<Connection> ConnectionPtr;
#endif

// the global events; each Connect* takes any callable, as the real
// templates do
#ifndef RSIA_REPAIRED__gazebo__event__Events
#define RSIA_REPAIRED__gazebo__event__Events 1
class Events
{
public:
  // every simulation step (a callback of void(const common::UpdateInfo&),
  // or of no argument for WorldUpdateEnd)
  template <typename T>
  static ConnectionPtr ConnectWorldUpdateBegin(T subscriber);
  template <typename T>
  static ConnectionPtr ConnectWorldUpdateEnd(T subscriber);
  template <typename T>
  static ConnectionPtr ConnectBeforePhysicsUpdate(T subscriber);
  // on what happens to the world, not at a rate
  template <typename T>
  static ConnectionPtr ConnectPause(T subscriber);
  template <typename T>
  static ConnectionPtr ConnectStep(T subscriber);
  template <typename T>
  static ConnectionPtr ConnectStop(T subscriber);
  template <typename T>
  static ConnectionPtr ConnectWorldCreated(T subscriber);
  template <typename T>
  static ConnectionPtr ConnectAddEntity(T subscriber);
  template <typename T>
  static ConnectionPtr ConnectDeleteEntity(T subscriber);
  template <typename T>
  static ConnectionPtr ConnectTimeReset(T subscriber);
  template <typename T>
  static ConnectionPtr ConnectWorldReset(T subscriber);
  template <typename T>
  static ConnectionPtr ConnectPreRender(T subscriber);
  template <typename T>
  static ConnectionPtr ConnectRender(T subscriber);
  template <typename T>
  static ConnectionPtr ConnectPostRender(T subscriber);
  template <typename T>
  static ConnectionPtr ConnectSigInt(T subscriber);
  static void DisconnectWorldUpdateBegin(ConnectionPtr subscriber);
  static void DisconnectWorldUpdateEnd(ConnectionPtr subscriber);
};
#endif

}  // namespace event
}  // namespace gazebo

// registration: the function gzserver looks up in the plugin's library
#ifndef GZ_REGISTER_MODEL_PLUGIN
#define GZ_REGISTER_MODEL_PLUGIN(classname) \
  extern "C" ::gazebo::ModelPlugin* RegisterPlugin();
#endif
#ifndef GZ_REGISTER_SENSOR_PLUGIN
#define GZ_REGISTER_SENSOR_PLUGIN(classname) \
  extern "C" ::gazebo::SensorPlugin* RegisterPlugin();
#endif
#ifndef GZ_REGISTER_WORLD_PLUGIN
#define GZ_REGISTER_WORLD_PLUGIN(classname) \
  extern "C" ::gazebo::WorldPlugin* RegisterPlugin();
#endif
#ifndef GZ_REGISTER_SYSTEM_PLUGIN
#define GZ_REGISTER_SYSTEM_PLUGIN(classname) \
  extern "C" ::gazebo::SystemPlugin* RegisterPlugin();
#endif

#endif  // RSIA_MODEL_PARTIAL_GAZEBO_H
