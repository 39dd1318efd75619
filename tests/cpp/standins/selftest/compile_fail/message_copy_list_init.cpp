// expect: explicit constructor
// rosidl message default constructors are explicit: `Msg m = {};` does not compile.
#include <sensor_msgs/msg/imu.hpp>

void f()
{
#ifdef RHI_EXPECT_FAIL
  sensor_msgs::msg::Imu m = {};
#else
  sensor_msgs::msg::Imu m{};
#endif
  (void)m;
}
