/* xf_version.h - the library's version (kept in step with CMakeLists.txt's project(VERSION), checked by CMake). */
#ifndef XF_VERSION_H
#define XF_VERSION_H

#define XF_VERSION_MAJOR  0
#define XF_VERSION_MINOR  1
#define XF_VERSION_PATCH  0
#define XF_VERSION_STRING "0.1.0"

#endif /* XF_VERSION_H */
