/**
 * @file
 * @brief The library's version (kept in step with CMakeLists.txt's project(VERSION), checked by CMake).
 */
#ifndef XF_VERSION_H
#define XF_VERSION_H

#define XF_VERSION_MAJOR  0       /**< major version: incompatible API changes */
#define XF_VERSION_MINOR  1       /**< minor version: additions */
#define XF_VERSION_PATCH  0       /**< patch version: fixes */
#define XF_VERSION_STRING "0.1.0" /**< "MAJOR.MINOR.PATCH" */

#endif /* XF_VERSION_H */
