// colcon-rsia model of <pluginlib/class_loader.hpp> (ROS 1 and ROS 2; ROS 1
// also has the name <pluginlib/class_loader.h>): the host side of plugins,
// loading a class by its name. The plugin classes it loads are analysed
// from their own packages; this is modelled so that host code parses and
// the instances it creates keep their types.
//
// createSharedInstance returns a std::shared_ptr in ROS 2 (when
// RSIA_MODEL_RCLCPP is defined) and a boost::shared_ptr in ROS 1.
#ifndef RSIA_MODEL_PLUGINLIB_CLASS_LOADER_HPP
#define RSIA_MODEL_PLUGINLIB_CLASS_LOADER_HPP

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <boost/shared_ptr.hpp>

namespace pluginlib
{

#ifdef RSIA_MODEL_RCLCPP
template <class T>
using RsiaSharedInstance = std::shared_ptr<T>;
#else
template <class T>
using RsiaSharedInstance = boost::shared_ptr<T>;
#endif

template <class T>
using UniquePtr = std::unique_ptr<T, std::function<void(T*)>>;

class ClassLoaderBase
{
public:
  virtual ~ClassLoaderBase();
  virtual std::vector<std::string> getDeclaredClasses() = 0;
  virtual std::string getName(const std::string& lookup_name) = 0;
  virtual bool isClassAvailable(const std::string& lookup_name) = 0;
  virtual std::string getClassDescription(const std::string& lookup_name) = 0;
  virtual std::string getClassType(const std::string& lookup_name) = 0;
  virtual std::string getClassPackage(const std::string& lookup_name) = 0;
  virtual std::string getBaseClassType() const = 0;
  virtual std::string getClassLibraryPath(const std::string& lookup_name) = 0;
  virtual std::vector<std::string> getPluginXmlPaths() = 0;
  virtual std::vector<std::string> getRegisteredLibraries() = 0;
  virtual std::string getPluginManifestPath(const std::string& lookup_name) = 0;
  virtual bool isClassLoaded(const std::string& lookup_name) = 0;
  virtual void loadLibraryForClass(const std::string& lookup_name) = 0;
  virtual void refreshDeclaredClasses() = 0;
  virtual int unloadLibraryForClass(const std::string& lookup_name) = 0;
};

template <class T>
class ClassLoader : public ClassLoaderBase
{
public:
  typedef typename std::map<std::string, std::string>::iterator ClassMapIterator;

  ClassLoader(std::string package, std::string base_class,
              std::string attrib_name = std::string("plugin"),
              std::vector<std::string> plugin_xml_paths = std::vector<std::string>());
  ~ClassLoader();

  RsiaSharedInstance<T> createInstance(const std::string& lookup_name);
  RsiaSharedInstance<T> createSharedInstance(const std::string& lookup_name);
  UniquePtr<T> createUniqueInstance(const std::string& lookup_name);
  T* createUnmanagedInstance(const std::string& lookup_name);

  std::vector<std::string> getDeclaredClasses();
  std::string getName(const std::string& lookup_name);
  bool isClassAvailable(const std::string& lookup_name);
  std::string getClassDescription(const std::string& lookup_name);
  std::string getClassType(const std::string& lookup_name);
  std::string getClassPackage(const std::string& lookup_name);
  std::string getBaseClassType() const;
  std::string getClassLibraryPath(const std::string& lookup_name);
  std::vector<std::string> getPluginXmlPaths();
  std::vector<std::string> getRegisteredLibraries();
  std::string getPluginManifestPath(const std::string& lookup_name);
  bool isClassLoaded(const std::string& lookup_name);
  void loadLibraryForClass(const std::string& lookup_name);
  void refreshDeclaredClasses();
  int unloadLibraryForClass(const std::string& lookup_name);
};

}  // namespace pluginlib

#endif  // RSIA_MODEL_PLUGINLIB_CLASS_LOADER_HPP
