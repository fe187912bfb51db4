# The report's in-page engine (wasm/CMakeLists.txt) built beside the native build, with
# emscripten, in <build>/wasm-engine: `momenta_wasm_engine` configures it there with emcmake and
# builds its module, build/wasm-engine/wasm/momenta_engine.js and .wasm. On every build
# (BUILD_ALWAYS): ninja decides there what changed. Its objects go through ccache as the native
# ones do. MOMENTA_WASM_ENGINE_JS and MOMENTA_WASM_ENGINE_WASM name the module's two files for the
# report (src/CMakeLists.txt embeds them) and the tests (tests/wasm).

find_program(MOMENTA_EMCMAKE emcmake)
if(NOT MOMENTA_EMCMAKE)
  message(FATAL_ERROR "MOMENTA_WASM_ENGINE needs emscripten's emcmake (Debian's emscripten; "
                      "scripts/bootstrap.sh installs it)")
endif()
include(ExternalProject)
set(wasm_engine_build ${PROJECT_BINARY_DIR}/wasm-engine)
set(MOMENTA_WASM_ENGINE_JS ${wasm_engine_build}/wasm/momenta_engine.js)
set(MOMENTA_WASM_ENGINE_WASM ${wasm_engine_build}/wasm/momenta_engine.wasm)
# Debian's emscripten runs its JavaScript optimizer under whatever node is first on PATH; a node
# not from Debian (NodeSource's) does not look in Debian's module folder for its acorn.
set(wasm_environment ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs)
set(wasm_launcher)
if(CMAKE_CXX_COMPILER_LAUNCHER)
  set(wasm_launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER}
                    -DCMAKE_C_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER})
endif()
ExternalProject_Add(momenta_wasm_engine
  SOURCE_DIR ${PROJECT_SOURCE_DIR}
  BINARY_DIR ${wasm_engine_build}
  CONFIGURE_COMMAND ${wasm_environment} ${MOMENTA_EMCMAKE} ${CMAKE_COMMAND}
                    -S <SOURCE_DIR> -B <BINARY_DIR> -G Ninja -DCMAKE_BUILD_TYPE=Release
                    ${wasm_launcher}
  BUILD_COMMAND ${wasm_environment} ${CMAKE_COMMAND} --build <BINARY_DIR> --target momenta_engine
  BUILD_ALWAYS ON
  INSTALL_COMMAND ""
  BUILD_BYPRODUCTS ${MOMENTA_WASM_ENGINE_JS} ${MOMENTA_WASM_ENGINE_WASM}
  USES_TERMINAL_BUILD ON)
