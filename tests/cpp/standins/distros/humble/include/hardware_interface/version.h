// rhi-gen test stand-in (not the real ROS 2 code): the ament_generate_version_header() output of
// hardware_interface 2.54.0, the newest release of the Humble branch (package.xml). Humble has
// version.h since 2.46.0; drivers gate on MAJOR (2 = Humble) or HARDWARE_INTERFACE_VERSION_GTE (the
// flat ?: chain of Humble's ament_cmake_gen_version_h template; Jazzy's nests it, same meaning).
#ifndef HARDWARE_INTERFACE__VERSION_H_
#define HARDWARE_INTERFACE__VERSION_H_

#define HARDWARE_INTERFACE_VERSION_MAJOR (2)
#define HARDWARE_INTERFACE_VERSION_MINOR (54)
#define HARDWARE_INTERFACE_VERSION_PATCH (0)
#define HARDWARE_INTERFACE_VERSION_STR "2.54.0"

#define HARDWARE_INTERFACE_VERSION_GTE(major, minor, patch) ( \
     (major < HARDWARE_INTERFACE_VERSION_MAJOR) ? true \
     : (major > HARDWARE_INTERFACE_VERSION_MAJOR) ? false \
     : (minor < HARDWARE_INTERFACE_VERSION_MINOR) ? true \
     : (minor > HARDWARE_INTERFACE_VERSION_MINOR) ? false \
     : (patch < HARDWARE_INTERFACE_VERSION_PATCH) ? true \
     : (patch > HARDWARE_INTERFACE_VERSION_PATCH) ? false \
     : true)

#endif  // HARDWARE_INTERFACE__VERSION_H_
