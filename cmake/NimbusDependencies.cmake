# Every dependency is a Debian 12 package (scripts/bootstrap installs them); see docs/design.md §1.
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)
find_package(OpenGL REQUIRED COMPONENTS OpenGL EGL)
pkg_check_modules(EPOXY REQUIRED IMPORTED_TARGET epoxy)
find_package(glfw3 CONFIG REQUIRED)
find_package(glm CONFIG REQUIRED)
find_package(TinyGLTF CONFIG REQUIRED)
find_package(nlohmann_json CONFIG REQUIRED)
find_package(OpenImageIO CONFIG REQUIRED)
find_package(embree 3 CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
# The media plugin's multiple-scattering grid runs its loops on TBB (also OpenVDB's dependency).
find_package(TBB CONFIG REQUIRED)
# Debian's libopenvdb-dev ships a find module (no config file) in a folder of its own; it also
# needs Boost.Iostreams, TBB and Blosc (bootstrap installs them).
list(APPEND CMAKE_MODULE_PATH "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/OpenVDB")
find_package(OpenVDB REQUIRED COMPONENTS openvdb)
if(NIMBUS_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(NIMBUS_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()

# Debian 12's OpenImageIO config lists /usr/include/opencv4 even when OpenCV's headers are not
# installed (OIIO only needs them for its optional OpenCV bridge, which we never include). Drop
# include directories that do not exist instead of pulling in all of OpenCV.
foreach(target OpenImageIO::OpenImageIO OpenImageIO::OpenImageIO_Util)
  if(TARGET ${target})
    get_target_property(dirs ${target} INTERFACE_INCLUDE_DIRECTORIES)
    if(dirs)
      set(existing "")
      foreach(dir ${dirs})
        if(EXISTS "${dir}" OR dir MATCHES "^\\$<")
          list(APPEND existing "${dir}")
        endif()
      endforeach()
      set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${existing}")
    endif()
  endif()
endforeach()
