# Shared compile settings for every Nimbus target.
add_library(nimbus_options INTERFACE)
target_compile_options(nimbus_options INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
  -Woverloaded-virtual -Wimplicit-fallthrough
  # GCC's null-dereference check runs after inlining: in a unity batch it fires inside nlohmann's
  # own headers. Unity targets skip it; the tests and the asan build (clang) keep it.
  $<$<NOT:$<BOOL:$<TARGET_PROPERTY:UNITY_BUILD>>>:-Wnull-dereference>
  # Descriptor structs are filled with designated initialisers that name only what differs from
  # the member defaults (sokol style); GCC's -Wextra would flag every omitted member.
  -Wno-missing-field-initializers
  $<$<BOOL:${NIMBUS_WERROR}>:-Werror>)
target_compile_definitions(nimbus_options INTERFACE
  GLM_ENABLE_EXPERIMENTAL
  $<$<CONFIG:Debug>:NIMBUS_DEBUG=1>)
# Coverage for libFuzzer in every library the fuzz targets link (tests/fuzz); needs clang.
if(NIMBUS_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "NIMBUS_FUZZ needs clang (the asan preset uses clang++-14)")
  endif()
  target_compile_options(nimbus_options INTERFACE -fsanitize=fuzzer-no-link)
endif()
if(NIMBUS_SANITIZE)
  target_compile_options(nimbus_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(nimbus_options INTERFACE -fsanitize=address,undefined)
endif()

# nimbus_module(NAME name SOURCES ... DEPS ...): a library whose public headers live in include/.
# Installed (the media plugin's package), its headers are under the prefix's include/ and it carries
# none of Nimbus's warning flags to the host.
function(nimbus_module)
  cmake_parse_arguments(M "" "NAME" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(${M_NAME} STATIC ${M_SOURCES})
  target_include_directories(${M_NAME} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
                                              $<INSTALL_INTERFACE:include>
                                       PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  target_link_libraries(${M_NAME} PUBLIC $<BUILD_INTERFACE:nimbus_options> ${M_DEPS} PRIVATE ${M_PRIVATE_DEPS})
endfunction()

# nimbus_forbid_links(TARGET t FORBIDDEN a b ...): fails the configure step when `t` links any of
# the forbidden targets, directly or through its dependencies (the plugin core's host contract).
function(_nimbus_collect_links target out)
  set(seen ${${out}})
  foreach(kind LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
    get_target_property(links ${target} ${kind})
    if(NOT links)
      continue()
    endif()
    foreach(link ${links})
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" link "${link}")
      if(link IN_LIST seen)
        continue()
      endif()
      list(APPEND seen ${link})
      if(TARGET ${link})
        _nimbus_collect_links(${link} seen)
      endif()
    endforeach()
  endforeach()
  set(${out} ${seen} PARENT_SCOPE)
endfunction()

function(nimbus_forbid_links)
  cmake_parse_arguments(F "" "TARGET" "FORBIDDEN" ${ARGN})
  set(links "")
  _nimbus_collect_links(${F_TARGET} links)
  foreach(forbidden ${F_FORBIDDEN})
    if(forbidden IN_LIST links)
      message(FATAL_ERROR "${F_TARGET} links ${forbidden}, which its host contract forbids (docs/integration.md)")
    endif()
  endforeach()
endfunction()
