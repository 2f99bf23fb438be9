// colcon-rsia model of <class_loader/register_macro.hpp>:
// CLASS_LOADER_REGISTER_CLASS defines, in an anonymous namespace, a struct
// ProxyExec<N> (N from __COUNTER__) whose constructor registers the class, and
// a static object of it. The analysis sees that constructor as a function of
// the package, so the struct keeps the real name.
#ifndef RSIA_MODEL_CLASS_LOADER_REGISTER_MACRO_HPP
#define RSIA_MODEL_CLASS_LOADER_REGISTER_MACRO_HPP

#include <string>

#include <class_loader/class_loader_core.hpp>

#define CLASS_LOADER_REGISTER_CLASS_INTERNAL_WITH_MESSAGE(Derived, Base, UniqueID, Message)       \
  namespace                                                                                      \
  {                                                                                              \
  struct ProxyExec##UniqueID                                                                     \
  {                                                                                              \
    typedef Derived _derived;                                                                    \
    typedef Base _base;                                                                          \
    ProxyExec##UniqueID()                                                                        \
    {                                                                                            \
      class_loader::impl::registerPlugin<_derived, _base>(#Derived, #Base);                      \
    }                                                                                            \
  };                                                                                             \
  static ProxyExec##UniqueID g_register_plugin_##UniqueID;                                       \
  }

#define CLASS_LOADER_REGISTER_CLASS_INTERNAL_HOP1_WITH_MESSAGE(Derived, Base, UniqueID, Message) \
  CLASS_LOADER_REGISTER_CLASS_INTERNAL_WITH_MESSAGE(Derived, Base, UniqueID, Message)

#define CLASS_LOADER_REGISTER_CLASS_WITH_MESSAGE(Derived, Base, Message) \
  CLASS_LOADER_REGISTER_CLASS_INTERNAL_HOP1_WITH_MESSAGE(Derived, Base, __COUNTER__, Message)

#define CLASS_LOADER_REGISTER_CLASS(Derived, Base) CLASS_LOADER_REGISTER_CLASS_WITH_MESSAGE(Derived, Base, "")

#endif  // RSIA_MODEL_CLASS_LOADER_REGISTER_MACRO_HPP
