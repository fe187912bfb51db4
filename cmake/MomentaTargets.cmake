# Helpers shared by every momenta target.

# Warnings and sanitizers for one of momenta's own targets.
function(momenta_configure_target target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
  if(MOMENTA_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(MOMENTA_SANITIZE)
    # UBSan's null and alignment checks guard every member access; they are a quarter of this
    # build's compile time (measured cold: 1785 → 1321 s of CPU for the build; the dynamics
    # library 118 s, 67 s with both off, 106 s with the null check alone off, 118 s with
    # alignment alone). What they would catch is caught elsewhere: a null object dereferenced
    # stops the run under ASan (a SEGV report with its stack, "address points to the zero page");
    # x86-64 reads misaligned data without fault, momenta reads raw bytes only through memcpy and
    # char pointers, and the fuzz build below keeps both checks on every file reader.
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined
                                             -fno-sanitize=null,alignment -fno-omit-frame-pointer
                                             -fno-sanitize-recover=all)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
  if(MOMENTA_FUZZ)
    # Coverage for libFuzzer in every library; the harnesses link the fuzzer's main.
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link,address,undefined
                                             -fno-omit-frame-pointer -fno-sanitize-recover=all)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()

# One translation unit per target (MOMENTA_UNITY_BUILD): Eigen's solvers and fmt are parsed and
# instantiated once per library instead of once per file — the command-line tool builds cold in
# a fraction of the time on two cores. Names private to a file must then differ between the files
# of a target (anonymous namespaces are shared).
function(momenta_unity_build target)
  if(MOMENTA_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 0)
  endif()
endfunction()

# momenta_add_library(<area> SOURCES ... DEPENDS ...): the library of one area, `momenta_<area>`,
# exported as `momenta::<area>`.
function(momenta_add_library area)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_DEPENDS;PRIVATE_DEPENDS" ${ARGN})
  set(target momenta_${area})
  add_library(${target} ${ARG_SOURCES})
  add_library(momenta::${area} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${area} POSITION_INDEPENDENT_CODE ON)
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_link_libraries(${target} PUBLIC ${ARG_PUBLIC_DEPENDS} PRIVATE ${ARG_PRIVATE_DEPENDS})
  momenta_configure_target(${target})
  momenta_unity_build(${target})
  install(TARGETS ${target} EXPORT momentaTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endfunction()
