// rhi-gen test stand-in (not the real ROS 2 code): the ament_generate_version_header() output of
// hardware_interface 6.8.0 (rolling; package.xml of the ros2_control branch). Drivers gate on MAJOR
// (4 = Jazzy, 5 = Kilted, 6 = Rolling/Lyrical) or HARDWARE_INTERFACE_VERSION_GTE.
#ifndef HARDWARE_INTERFACE__VERSION_H_
#define HARDWARE_INTERFACE__VERSION_H_

#define HARDWARE_INTERFACE_VERSION_MAJOR (6)
#define HARDWARE_INTERFACE_VERSION_MINOR (8)
#define HARDWARE_INTERFACE_VERSION_PATCH (0)
#define HARDWARE_INTERFACE_VERSION_STR "6.8.0"

#define HARDWARE_INTERFACE_VERSION_GTE(major, minor, patch) ( \
     (major < HARDWARE_INTERFACE_VERSION_MAJOR) ? true \
     : ((major > HARDWARE_INTERFACE_VERSION_MAJOR) ? false \
     : ((minor < HARDWARE_INTERFACE_VERSION_MINOR) ? true \
     : ((minor > HARDWARE_INTERFACE_VERSION_MINOR) ? false \
     : ((patch < HARDWARE_INTERFACE_VERSION_PATCH) ? true \
     : ((patch > HARDWARE_INTERFACE_VERSION_PATCH) ? false \
     : true))))))

#endif  // HARDWARE_INTERFACE__VERSION_H_
