// rhi-gen test stand-in (not the real unitree_sdk2): unitree::common::Thread / ThreadPtr.
// In the SDK, Thread derives from FutureWrapper whose `virtual bool Wait(int64_t microsec = 0)`
// a RecurrentThread overrides to stop its loop and wait for the thread; the stand-in keeps only
// that virtual Wait (plus the name/cpu accessors). The one-shot Thread(func, args...) and
// CreateThread[Ex] helpers are not provided.
#ifndef __UT_THREAD_HPP__
#define __UT_THREAD_HPP__

#include <cstdint>
#include <memory>
#include <string>

#include <unitree/common/thread/thread_decl.hpp>

namespace unitree
{
namespace common
{
class Thread
{
public:
  Thread()
  : mThreadId(0), mCpuId(UT_CPU_ID_NONE)
  {}

  Thread(const std::string & name, int32_t cpuId)
  : mThreadId(0), mName(name), mCpuId(cpuId)
  {}

  virtual ~Thread() = default;

  /// Wait for the thread to finish (microsec == 0: no time limit). Returns true if it finished.
  virtual bool Wait(int64_t microsec = 0)
  {
    (void)microsec;
    return true;
  }

  uint64_t GetThreadId() const {return mThreadId;}

protected:
  uint64_t mThreadId;
  std::string mName;
  int32_t mCpuId;
};

typedef std::shared_ptr<Thread> ThreadPtr;

}  // namespace common
}  // namespace unitree

#endif  // __UT_THREAD_HPP__
