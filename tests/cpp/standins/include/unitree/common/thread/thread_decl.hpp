// rhi-gen test stand-in (not the real unitree_sdk2): the thread helper macros of the SDK.
#ifndef __UT_THREAD_DECL_HPP__
#define __UT_THREAD_DECL_HPP__

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>

#define __UT_THREAD_DECL_TMPL_FUNC_ARG__ \
  template<class Func, class ... Args>

#define __UT_THREAD_TMPL_FUNC_ARG__ \
  Func && func, Args && ... args

#define __UT_THREAD_BIND_FUNC_ARG__ \
  std::forward<Func>(func), std::forward<Args>(args) ...

#define UT_CPU_ID_NONE  -1

#endif  // __UT_THREAD_DECL_HPP__
