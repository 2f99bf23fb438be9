// colcon-rsia model of <class_loader/class_loader_core.hpp>.
#ifndef RSIA_MODEL_CLASS_LOADER_CLASS_LOADER_CORE_HPP
#define RSIA_MODEL_CLASS_LOADER_CLASS_LOADER_CORE_HPP

#include <memory>
#include <string>

namespace class_loader
{

namespace impl
{

class AbstractMetaObjectBase;
template <typename T>
using UniquePtr = std::unique_ptr<T>;

template <typename Derived, typename Base>
UniquePtr<AbstractMetaObjectBase> registerPlugin(const std::string& class_name,
                                                 const std::string& base_class_name);

}  // namespace impl

}  // namespace class_loader

#endif  // RSIA_MODEL_CLASS_LOADER_CLASS_LOADER_CORE_HPP
