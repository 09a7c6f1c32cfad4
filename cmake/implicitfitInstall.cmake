# `cmake --install` of implicitfit as a package others build on (find_package(implicitfit)):
#   include/implicitfit/*.h            the public API (include/implicitfit/): the jobs' declarations
#                                      and thin umbrella headers
#   include/implicitfit/internal/...   the headers they include (model/, fit/, datasets/, jobs/), as
#                                      Ceres installs ceres/internal/: not API, may change
#   lib/libimplicitfit_*.a             the static libraries model, fit, datasets, jobs
#   lib/cmake/implicitfit/             implicitfitConfig.cmake, its version file, the targets
#   bin/implicitfit                    the command line
# Targets: implicitfit::implicitfit (all four), implicitfit::model, ::fit, ::datasets, ::jobs.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(IMPLICITFIT_INTERNAL_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}/implicitfit/internal")
set(IMPLICITFIT_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/implicitfit")

# In the tree the include root is the repository root (model/..., fit/...) plus include/ for
# the public headers; installed, include/ and include/implicitfit/internal/.
target_include_directories(implicitfit_model PUBLIC
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
  $<INSTALL_INTERFACE:${IMPLICITFIT_INTERNAL_INCLUDEDIR}>)

if(IMPLICITFIT_SANITIZE)  # a consumer of sanitized static libraries links the runtimes too
  target_link_options(implicitfit_model INTERFACE
    $<INSTALL_INTERFACE:${IMPLICITFIT_SANITIZER_FLAGS}>)
endif()

add_library(implicitfit_library INTERFACE)
add_library(implicitfit::implicitfit ALIAS implicitfit_library)
target_link_libraries(implicitfit_library INTERFACE implicitfit_model implicitfit_fit
  implicitfit_datasets implicitfit_jobs)
set_target_properties(implicitfit_library PROPERTIES EXPORT_NAME implicitfit)
set_target_properties(implicitfit_model PROPERTIES EXPORT_NAME model)
set_target_properties(implicitfit_fit PROPERTIES EXPORT_NAME fit)
set_target_properties(implicitfit_datasets PROPERTIES EXPORT_NAME datasets)
set_target_properties(implicitfit_jobs PROPERTIES EXPORT_NAME jobs)
# implicitfit_warnings is linked privately (compile flags of this project only); a static
# library's private links still appear in its export as $<LINK_ONLY:...>, so it is exported.
install(TARGETS implicitfit_library implicitfit_model implicitfit_fit implicitfit_datasets
                implicitfit_jobs
                implicitfit_warnings
  EXPORT implicitfitTargets
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
install(TARGETS implicitfit RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")

install(DIRECTORY "${PROJECT_SOURCE_DIR}/include/implicitfit"
  DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}" FILES_MATCHING PATTERN "*.h")
# Every header of the library folders (no PCL include is in any of them: docs/design.md).
foreach(folder model fit datasets jobs)
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/${folder}/"
    DESTINATION "${IMPLICITFIT_INTERNAL_INCLUDEDIR}/${folder}"
    FILES_MATCHING PATTERN "*.h" PATTERN "data" EXCLUDE)
endforeach()

install(EXPORT implicitfitTargets NAMESPACE implicitfit:: DESTINATION "${IMPLICITFIT_CMAKEDIR}")
configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/implicitfitConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/implicitfitConfig.cmake" INSTALL_DESTINATION "${IMPLICITFIT_CMAKEDIR}")
# 0.x: a minor version may break the API, so only the same minor version is compatible.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/implicitfitConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/implicitfitConfig.cmake"
  "${PROJECT_BINARY_DIR}/implicitfitConfigVersion.cmake" DESTINATION "${IMPLICITFIT_CMAKEDIR}")
