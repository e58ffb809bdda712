# The media plugin as a package (docs/integration.md §2): `cmake --install build/release --prefix P`
# lays out its headers, static libraries and shaders, and P/lib/cmake/NimbusMedia, so that a host
# in its own repository writes
#     find_package(NimbusMedia CONFIG REQUIRED)
#     target_link_libraries(my_engine PRIVATE NimbusMedia::media)
# The same target name works in-tree (add_subdirectory): NimbusMedia::media is an alias there.
#
# Does not: install Nimbus's engine, editor, sandbox or the reference renderer: only what a host
# links (nimbus_media_gpu, nimbus_media_gltf and what they need: nimbus_media_core, nimbus_gpu,
# nimbus_base). The libraries carry their shaders (nimbus/gpu/builtin_shaders.h); the .glsl files
# are installed too, for reading, and for a host that passes them as NIMBUS_SHADER_DIR.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# One target for a host: the contract, the passes and the scene extension's parser.
add_library(nimbus_media INTERFACE)
target_link_libraries(nimbus_media INTERFACE nimbus_media_gpu nimbus_media_gltf)
set_target_properties(nimbus_media PROPERTIES EXPORT_NAME media)
add_library(NimbusMedia::media ALIAS nimbus_media)

set(NIMBUS_MEDIA_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/NimbusMedia)
install(TARGETS nimbus_media nimbus_media_gpu nimbus_media_gltf nimbus_media_core nimbus_gpu nimbus_base
        EXPORT NimbusMediaTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(headers engine/base engine/gpu plugins/participating_media/core plugins/participating_media/gltf)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${headers}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
# The plugin's shaders and the shared includes they use; the engine's own passes are not the plugin's.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/shaders/media ${PROJECT_SOURCE_DIR}/shaders/common
        DESTINATION ${CMAKE_INSTALL_DATADIR}/nimbus/shaders)
install(EXPORT NimbusMediaTargets NAMESPACE NimbusMedia:: DESTINATION ${NIMBUS_MEDIA_CMAKE_DIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/NimbusMediaConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/NimbusMediaConfig.cmake
  INSTALL_DESTINATION ${NIMBUS_MEDIA_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/NimbusMediaConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/NimbusMediaConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/NimbusMediaConfigVersion.cmake
        DESTINATION ${NIMBUS_MEDIA_CMAKE_DIR})
