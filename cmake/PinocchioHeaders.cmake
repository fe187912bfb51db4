# momenta_pinocchio_headers(<target> <source dir>): Pinocchio's algorithms as header code for the
# side-by-side benchmark (bench/pinocchio_comparison_bench.cpp). Pinocchio's own build generates
# three small headers (its version, export and deprecation macros); they are written into the
# build folder here, so a plain source checkout (3.x) is enough. Eigen and Boost's headers are
# momenta's own dependencies already.
function(momenta_pinocchio_headers target source_dir)
  if(NOT EXISTS "${source_dir}/include/pinocchio/algorithm/aba-derivatives.hpp")
    message(FATAL_ERROR "MOMENTA_PINOCCHIO_SOURCE='${source_dir}' is not a Pinocchio source "
                        "checkout (no include/pinocchio/algorithm/aba-derivatives.hpp)")
  endif()
  set(generated "${CMAKE_CURRENT_BINARY_DIR}/pinocchio_generated/pinocchio")
  file(WRITE "${generated}/config.hpp" [=[#pragma once
#define PINOCCHIO_MAJOR_VERSION 3
#define PINOCCHIO_MINOR_VERSION 7
#define PINOCCHIO_PATCH_VERSION 0
#define PINOCCHIO_VERSION "3.7.0"
#define PINOCCHIO_DLLAPI
#define PINOCCHIO_LOCAL
#define PINOCCHIO_EXPORT
]=])
  file(WRITE "${generated}/deprecated.hpp" [=[#pragma once
#define PINOCCHIO_DEPRECATED __attribute__((deprecated))
#define PINOCCHIO_DEPRECATED_MESSAGE(message) __attribute__((deprecated(message)))
]=])
  file(WRITE "${generated}/warning.hpp" "#pragma once\n#define PINOCCHIO_WARNING(message)\n")
  target_include_directories(${target} SYSTEM PRIVATE "${CMAKE_CURRENT_BINARY_DIR}/pinocchio_generated"
                                                      "${source_dir}/include")
  target_link_libraries(${target} PRIVATE Boost::headers)
endfunction()
