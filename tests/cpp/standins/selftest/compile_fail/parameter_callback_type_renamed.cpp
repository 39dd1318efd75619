// expect: OnParametersSetCallbackType|deprecated
// distros: jazzy kilted rolling
// The callback type is OnParametersSetCallbackType on Humble; Jazzy renames it OnSetParametersCallbackType
// (the old name deprecated), Kilted removes the old name.
#include <rclcpp/node.hpp>

#ifdef RHI_EXPECT_FAIL
using Callback = rclcpp::node_interfaces::OnSetParametersCallbackHandle::OnParametersSetCallbackType;
#else
using Callback = rclcpp::node_interfaces::OnSetParametersCallbackHandle::OnSetParametersCallbackType;
#endif
Callback f() {return Callback();}
