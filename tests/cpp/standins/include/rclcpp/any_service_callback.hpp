// rhi-gen test stand-in (not the real ROS 2 code): rclcpp::AnyServiceCallback<ServiceT>, the
// callback forms Node::create_service accepts (the same on rclcpp 16, 28 and 29+):
//   void(std::shared_ptr<Request>, std::shared_ptr<Response>)                     (also const ... / const &)
//   void(std::shared_ptr<rmw_request_id_t>, std::shared_ptr<Request>, std::shared_ptr<Response>)
//   void(std::shared_ptr<rmw_request_id_t>, std::shared_ptr<Request>)            deferred response: the
//   void(std::shared_ptr<Service<ServiceT>>, std::shared_ptr<rmw_request_id_t>,  callback (or later code)
//        std::shared_ptr<Request>)                                               calls send_response()
// A callable whose parameters are exactly one of these is taken as that form; otherwise, like rclcpp's
// std::variant assignment, it must be callable as exactly one of them (e.g. std::shared_ptr<const
// Request>). Anything else (const Request &, Response &, generic lambdas, ...) does not compile.
// A null std::function / function pointer throws std::invalid_argument, as in rclcpp.
#ifndef RCLCPP__ANY_SERVICE_CALLBACK_HPP_
#define RCLCPP__ANY_SERVICE_CALLBACK_HPP_

#include <functional>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>

#include "rclcpp/visibility_control.hpp"
#include "rmw/types.h"
#include "rhi_fake/detail/function_traits.hpp"

namespace rclcpp
{

template<typename ServiceT>
class Service;

template<typename ServiceT>
class AnyServiceCallback
{
  using Request = typename ServiceT::Request;
  using Response = typename ServiceT::Response;
  using SharedPtrCallback =
    std::function<void (std::shared_ptr<Request>, std::shared_ptr<Response>)>;
  using SharedPtrWithRequestHeaderCallback = std::function<
    void (std::shared_ptr<rmw_request_id_t>, std::shared_ptr<Request>, std::shared_ptr<Response>)>;
  using SharedPtrDeferResponseCallback =
    std::function<void (std::shared_ptr<rmw_request_id_t>, std::shared_ptr<Request>)>;
  using SharedPtrDeferResponseCallbackWithServiceHandle = std::function<
    void (
      std::shared_ptr<rclcpp::Service<ServiceT>>, std::shared_ptr<rmw_request_id_t>,
      std::shared_ptr<Request>)>;

  template<typename CallbackT, typename F>
  static constexpr bool exactly()
  {
    using traits = ::rhi_fake::detail::ft::of<CallbackT>;
    return std::is_same<typename traits::arguments, typename ::rhi_fake::detail::ft::of<F>::arguments>::value;
  }

  template<typename CallbackT, typename F>
  static constexpr bool convertible() {return std::is_constructible<F, CallbackT>::value;}

  template<typename T, typename = void>
  struct can_be_nullptr : std::false_type {};
  template<typename T>
  struct can_be_nullptr<T, std::void_t<
      decltype(std::declval<T>() == nullptr), decltype(std::declval<T &>() = nullptr)>>
    : std::true_type {};

public:
  AnyServiceCallback()
  : callback_(std::monostate{}) {}

  template<typename CallbackT>
  void set(CallbackT && callback)
  {
    using C = std::decay_t<CallbackT>;
    if constexpr (can_be_nullptr<C>::value) {
      if (!callback) {
        throw std::invalid_argument("AnyServiceCallback::set(): callback cannot be nullptr");
      }
    }
    if constexpr (exactly<C, SharedPtrCallback>()) {
      callback_.template emplace<SharedPtrCallback>(std::forward<CallbackT>(callback));
    } else if constexpr (exactly<C, SharedPtrWithRequestHeaderCallback>()) {
      callback_.template emplace<SharedPtrWithRequestHeaderCallback>(std::forward<CallbackT>(callback));
    } else if constexpr (exactly<C, SharedPtrDeferResponseCallback>()) {
      callback_.template emplace<SharedPtrDeferResponseCallback>(std::forward<CallbackT>(callback));
    } else if constexpr (exactly<C, SharedPtrDeferResponseCallbackWithServiceHandle>()) {
      callback_.template emplace<SharedPtrDeferResponseCallbackWithServiceHandle>(
        std::forward<CallbackT>(callback));
    } else {
      constexpr int viable =
        int(convertible<C, SharedPtrCallback>()) +
        int(convertible<C, SharedPtrWithRequestHeaderCallback>()) +
        int(convertible<C, SharedPtrDeferResponseCallback>()) +
        int(convertible<C, SharedPtrDeferResponseCallbackWithServiceHandle>());
      static_assert(
        viable == 1,
        "rclcpp: unsupported service callback signature; use "
        "void(std::shared_ptr<Request>, std::shared_ptr<Response>), "
        "void(std::shared_ptr<rmw_request_id_t>, std::shared_ptr<Request>, std::shared_ptr<Response>) "
        "or a deferred-response form (rclcpp/any_service_callback.hpp)");
      if constexpr (viable == 1) {
        callback_ = std::forward<CallbackT>(callback);
      }
    }
  }

  /// Runs the callback; returns the response to send (nullptr for the deferred forms).
  std::shared_ptr<Response> dispatch(
    const std::shared_ptr<rclcpp::Service<ServiceT>> & service_handle,
    const std::shared_ptr<rmw_request_id_t> & request_header,
    std::shared_ptr<Request> request)
  {
    if (std::holds_alternative<std::monostate>(callback_)) {
      throw std::runtime_error{"unexpected request without any callback set"};
    }
    if (auto * defer = std::get_if<SharedPtrDeferResponseCallback>(&callback_)) {
      (*defer)(request_header, std::move(request));
      return nullptr;
    }
    if (auto * defer_h = std::get_if<SharedPtrDeferResponseCallbackWithServiceHandle>(&callback_)) {
      (*defer_h)(service_handle, request_header, std::move(request));
      return nullptr;
    }
    auto response = std::make_shared<Response>();
    if (auto * plain = std::get_if<SharedPtrCallback>(&callback_)) {
      (*plain)(std::move(request), response);
    } else if (auto * with_header = std::get_if<SharedPtrWithRequestHeaderCallback>(&callback_)) {
      (*with_header)(request_header, std::move(request), response);
    }
    return response;
  }

private:
  std::variant<
    std::monostate,
    SharedPtrCallback,
    SharedPtrWithRequestHeaderCallback,
    SharedPtrDeferResponseCallback,
    SharedPtrDeferResponseCallbackWithServiceHandle> callback_;
};

}  // namespace rclcpp

#endif  // RCLCPP__ANY_SERVICE_CALLBACK_HPP_
