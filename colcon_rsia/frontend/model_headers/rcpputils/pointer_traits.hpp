// colcon-rsia model of <rcpputils/pointer_traits.hpp>: whether a type is a
// raw or smart pointer, and what it points to. Real code checks pointers in
// static_asserts and macros (hardware_interface's THROW_ON_NULLPTR), so the
// traits must be class templates with a constant `value`.
#ifndef RSIA_MODEL_RCPPUTILS_POINTER_TRAITS_HPP
#define RSIA_MODEL_RCPPUTILS_POINTER_TRAITS_HPP

#include <memory>
#include <type_traits>

namespace rcpputils
{

template <class T>
struct is_smart_pointer : std::false_type
{
};
template <class T>
struct is_smart_pointer<std::shared_ptr<T>> : std::true_type
{
};
template <class T, class D>
struct is_smart_pointer<std::unique_ptr<T, D>> : std::true_type
{
};

template <class T>
struct is_pointer
{
  static constexpr bool value =
    std::is_pointer<typename std::remove_cv<T>::type>::value ||
    is_smart_pointer<typename std::remove_cv<T>::type>::value;
};

template <class T>
struct remove_pointer
{
  using type = typename std::remove_pointer<T>::type;
};
template <class T>
struct remove_pointer<std::shared_ptr<T>>
{
  using type = T;
};
template <class T, class D>
struct remove_pointer<std::unique_ptr<T, D>>
{
  using type = T;
};

}  // namespace rcpputils

#endif  // RSIA_MODEL_RCPPUTILS_POINTER_TRAITS_HPP
