# SPDX-License-Identifier: MIT
# What `cmake --install` puts where (GNUInstallDirs), for a prefix P:
#   P/include/rb, P/include/mu          the public headers
#   P/lib/librb.a, libmu.a              or, with BUILD_SHARED_LIBS, librb.so.*
#   P/lib/cmake/sinew/                  sinewConfig.cmake, its version file and
#                                       the targets sinew::rb and sinew::mu
#   P/lib/pkgconfig/sinew-rb.pc, sinew-mu.pc
#   P/bin/sinew, sinew-view             the programs (tools/CMakeLists.txt)
#   P/share/sinew/                      the built-in models (and the worm's
#                                       profile image), the curve tables
#                                       and the control files (libmu has its own
#                                       copies compiled in; these are to read,
#                                       copy and change, with SINEW_DATA_DIR)
#   P/share/doc/sinew/                  README, LICENSE, CHANGELOG, docs/ (examples included)
include(CMakePackageConfigHelpers)

set(sinew_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/sinew)
get_property(sinew_libraries GLOBAL PROPERTY sinew_installed_libraries)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/include/rb ${PROJECT_SOURCE_DIR}/musculo/include/mu
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT development)
install(TARGETS ${sinew_libraries}
        EXPORT sinewTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT development
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
install(EXPORT sinewTargets
        NAMESPACE sinew::
        DESTINATION ${sinew_cmake_dir}
        COMPONENT development)

# sinewConfig.cmake: a static libmu.a needs its private dependencies (GSL,
# jansson, libpng, NLopt) at the consumer's link, found with pkg-config.
set(SINEW_SHARED_LIBRARIES ${BUILD_SHARED_LIBS})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/sinewConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/sinewConfig.cmake
                              INSTALL_DESTINATION ${sinew_cmake_dir})
# Before 1.0 a minor release may break the API: 0.2.x satisfies
# find_package(sinew 0.2) but not 0.1 or 0.3.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/sinewConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/sinewConfig.cmake ${PROJECT_BINARY_DIR}/sinewConfigVersion.cmake
        DESTINATION ${sinew_cmake_dir}
        COMPONENT development)

# pkg-config files, with the libraries' private dependencies for --static.
# The prefix is found from the .pc file's own folder (pkg-config's
# ${pcfiledir}), so a moved install still points at itself.
file(RELATIVE_PATH SINEW_PC_PREFIX_FROM_PCFILEDIR ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" SINEW_PC_PREFIX_FROM_PCFILEDIR "${SINEW_PC_PREFIX_FROM_PCFILEDIR}")
foreach(library rb mu)
    configure_file(${PROJECT_SOURCE_DIR}/cmake/sinew-${library}.pc.in
                   ${PROJECT_BINARY_DIR}/sinew-${library}.pc @ONLY)
    install(FILES ${PROJECT_BINARY_DIR}/sinew-${library}.pc
            DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
            COMPONENT development)
endforeach()

install(FILES ${PROJECT_SOURCE_DIR}/models/sample.json ${PROJECT_SOURCE_DIR}/models/arm.json
              ${PROJECT_SOURCE_DIR}/models/leg.json ${PROJECT_SOURCE_DIR}/models/leg-unlimited.json
              ${PROJECT_SOURCE_DIR}/models/worm.json ${PROJECT_SOURCE_DIR}/models/worm-pool.png
              ${PROJECT_SOURCE_DIR}/models/data/hill-curves.csv
        DESTINATION ${CMAKE_INSTALL_DATADIR}/sinew
        COMPONENT runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/models/controls
        DESTINATION ${CMAKE_INSTALL_DATADIR}/sinew
        COMPONENT runtime)
# The model file format is docs/model-format.md (models/README.md only
# points to it, and would replace the top-level README.md here).
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/CHANGELOG.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR}
        COMPONENT documentation)
# docs/ keeps its name, so the README's links (docs/cli.md, ...) work in the
# installed copy too, and docs/README.md does not replace the README. The
# examples' CMakeLists.txt is installed with them; docs/CMakeLists.txt is not.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/
        DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
        COMPONENT documentation
        REGEX "/docs/CMakeLists\\.txt$" EXCLUDE
        PATTERN "*.in" EXCLUDE)
