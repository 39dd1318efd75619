// rhi-gen test stand-in (not the real ROS 2 code). Callable introspection used by the fake
// rclcpp to decide, at compile time, which subscription / timer callback signature a driver used.
// Mirrors what rclcpp::function_traits can deduce (lambdas, functors, std::function, function
// pointers, and libstdc++ std::bind of a member or free function); a generic lambda or an
// overloaded functor is rejected, as in rclcpp.
#pragma once

#include <cstddef>
#include <functional>
#include <tuple>
#include <type_traits>

namespace rhi_fake {
namespace detail {
namespace ft {

template<typename R, typename... A>
struct signature
{
  using return_type = R;
  using arguments = std::tuple<A...>;
  static constexpr std::size_t arity = sizeof...(A);
};

template<typename MemFn>
struct call_operator;  // deduced from &T::operator()

#define RHI_FT_CALL_OPERATOR(QUALS) \
  template<typename C, typename R, typename... A> \
  struct call_operator<R (C::*)(A...) QUALS> : signature<R, A...> {};
RHI_FT_CALL_OPERATOR()
RHI_FT_CALL_OPERATOR(const)
RHI_FT_CALL_OPERATOR(noexcept)
RHI_FT_CALL_OPERATOR(const noexcept)
RHI_FT_CALL_OPERATOR(&)
RHI_FT_CALL_OPERATOR(const &)
#undef RHI_FT_CALL_OPERATOR

// Primary: a class type with exactly one, non-template operator().
template<typename T>
struct traits : call_operator<decltype(&T::operator())> {};

template<typename R, typename... A>
struct traits<R(A...)> : signature<R, A...> {};
template<typename R, typename... A>
struct traits<R(A...) noexcept> : signature<R, A...> {};
template<typename R, typename... A>
struct traits<R (*)(A...)> : signature<R, A...> {};
template<typename R, typename... A>
struct traits<R (*)(A...) noexcept> : signature<R, A...> {};

// A bare member function pointer is "callable" with the object as first argument (as rclcpp
// reports it), which never matches a subscription or timer signature.
template<typename C, typename R, typename... A>
struct traits<R (C::*)(A...)> : signature<R, C &, A...> {};
template<typename C, typename R, typename... A>
struct traits<R (C::*)(A...) const> : signature<R, C &, A...> {};

#if defined(__GLIBCXX__)
// std::bind(&Class::method, obj, placeholders...): the method's own parameters, like rclcpp.
template<typename C, typename R, typename... A, typename... F>
struct traits<std::_Bind<R (C::*(F...))(A...)>> : signature<R, A...> {};
template<typename C, typename R, typename... A, typename... F>
struct traits<std::_Bind<R (C::*(F...))(A...) const>> : signature<R, A...> {};
template<typename C, typename R, typename... A, typename... F>
struct traits<std::_Bind<R (C::*(F...))(A...) noexcept>> : signature<R, A...> {};
template<typename C, typename R, typename... A, typename... F>
struct traits<std::_Bind<R (C::*(F...))(A...) const noexcept>> : signature<R, A...> {};
// std::bind(&free_function, args...)
template<typename R, typename... A, typename... F>
struct traits<std::_Bind<R (*(F...))(A...)>> : signature<R, A...> {};
#endif

template<typename T>
using of = traits<std::remove_cv_t<std::remove_reference_t<T>>>;

template<typename T, std::size_t I>
using arg_t = std::tuple_element_t<I, typename of<T>::arguments>;

}  // namespace ft
}  // namespace detail
}  // namespace rhi_fake
