#pragma once
// Versions of the plugin ABI and of the SDK, and the build identity a plugin must share
// with the kernel that loads it (same compiler family and major version, same C++
// standard library ABI), because plugin and kernel exchange std::string, std::function
// and Eigen objects across the library boundary.

#define MOREAU_ABI_VERSION 11
#define MOREAU_SDK_VERSION "0.1.0"

#define MOREAU_STRINGIFY_(x) #x
#define MOREAU_STRINGIFY(x) MOREAU_STRINGIFY_(x)

#if defined(__clang__)
#define MOREAU_COMPILER_ID "clang-" MOREAU_STRINGIFY(__clang_major__)
#elif defined(__GNUC__)
#define MOREAU_COMPILER_ID "gcc-" MOREAU_STRINGIFY(__GNUC__)
#else
#define MOREAU_COMPILER_ID "unknown"
#endif

#if defined(_GLIBCXX_USE_CXX11_ABI)
#define MOREAU_STDLIB_ID "libstdc++-cxx11abi" MOREAU_STRINGIFY(_GLIBCXX_USE_CXX11_ABI)
#elif defined(_LIBCPP_VERSION)
#define MOREAU_STDLIB_ID "libc++-" MOREAU_STRINGIFY(_LIBCPP_ABI_VERSION)
#else
#define MOREAU_STDLIB_ID "unknown-stdlib"
#endif

/// What kernel and plugin compare, besides the ABI version number.
#define MOREAU_BUILD_ID MOREAU_COMPILER_ID "/" MOREAU_STDLIB_ID
