# Shared compile settings for every Nimbus target.
add_library(nimbus_options INTERFACE)
target_compile_options(nimbus_options INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
  -Woverloaded-virtual -Wnull-dereference -Wimplicit-fallthrough
  # Descriptor structs are filled with designated initialisers that name only what differs from
  # the member defaults (sokol style); GCC's -Wextra would flag every omitted member.
  -Wno-missing-field-initializers
  $<$<BOOL:${NIMBUS_WERROR}>:-Werror>)
target_compile_definitions(nimbus_options INTERFACE
  GLM_ENABLE_EXPERIMENTAL
  $<$<CONFIG:Debug>:NIMBUS_DEBUG=1>)
if(NIMBUS_SANITIZE)
  target_compile_options(nimbus_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(nimbus_options INTERFACE -fsanitize=address,undefined)
endif()

# nimbus_module(NAME name SOURCES ... DEPS ...): a library whose public headers live in include/.
function(nimbus_module)
  cmake_parse_arguments(M "" "NAME" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(${M_NAME} STATIC ${M_SOURCES})
  target_include_directories(${M_NAME} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include
                                       PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  target_link_libraries(${M_NAME} PUBLIC nimbus_options ${M_DEPS} PRIVATE ${M_PRIVATE_DEPS})
endfunction()
