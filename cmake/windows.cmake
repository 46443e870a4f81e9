# The FMUs' Windows binaries (binaries/win64/RockingWall.dll, Diaphragm.dll, Building.dll,
# BuildingWithWalls.dll), cross-compiled with
# Debian's mingw-w64 by the ExternalProject rw_win64 (cmake/win64/CMakeLists.txt with
# cmake/toolchain-mingw-w64.cmake), and their tests, run under wine. Included by
# fmu_src/CMakeLists.txt, whose rw_add_fmu (fmu_src/fmu_package.cmake) packs RW_WIN64_BINARY_DIR/NAME.dll into NAME.fmu.
#
# RW_WIN64: ON, OFF or AUTO (the default): AUTO is ON when the cross compiler is found, OFF when
# not and under the sanitizers (those builds test the Linux binaries; the Windows build would only
# be built twice). AUTO is decided again at every configure, so a build folder configured before
# mingw-w64 was installed (scripts/setup.sh --with-windows) builds the Windows binaries after it.
find_program(RW_MINGW_GCC x86_64-w64-mingw32-gcc)
set(RW_WIN64 AUTO CACHE STRING "Cross-compile the FMUs' win64 binaries with mingw-w64: ON, OFF or AUTO")
set_property(CACHE RW_WIN64 PROPERTY STRINGS AUTO ON OFF)
if(RW_WIN64 STREQUAL "AUTO")
  if(RW_MINGW_GCC AND NOT RW_SANITIZE)
    set(RW_WIN64 ON)
  else()
    set(RW_WIN64 OFF)
  endif()
endif()
if(NOT RW_WIN64)
  message(STATUS "Windows binaries: off (RW_WIN64; cross compiler: ${RW_MINGW_GCC})")
  if(NOT RW_MINGW_GCC AND NOT RW_SANITIZE AND RW_BUILD_TESTS)
    add_test(NAME win64_binaries COMMAND sh -c
             "echo 'SKIPPED: x86_64-w64-mingw32-gcc not found (Debian: scripts/setup.sh --with-windows); the FMUs have no win64 binaries'; exit 77")
    set_tests_properties(win64_binaries PROPERTIES SKIP_RETURN_CODE 77)
  endif()
  return()
endif()
if(NOT RW_MINGW_GCC)
  message(FATAL_ERROR "RW_WIN64=ON needs x86_64-w64-mingw32-gcc (Debian: apt-get install mingw-w64)")
endif()

include(ExternalProject)
set(RW_WIN64_BINARY_DIR ${CMAKE_BINARY_DIR}/win64)
ExternalProject_Add(rw_win64
  SOURCE_DIR ${CMAKE_SOURCE_DIR}/cmake/win64
  BINARY_DIR ${RW_WIN64_BINARY_DIR}
  PREFIX ${CMAKE_BINARY_DIR}/win64-ep
  CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${CMAKE_SOURCE_DIR}/cmake/toolchain-mingw-w64.cmake
             -DCMAKE_BUILD_TYPE=Release
             -DRW_SOURCE_DIR=${CMAKE_SOURCE_DIR}
             -DFMI2_HEADERS_DIR=${FMI2_HEADERS_DIR}
             -DRW_WIN64_TESTS=${RW_BUILD_TESTS}
  BUILD_ALWAYS ON # its own build decides what is out of date (the sources are outside its tree)
  INSTALL_COMMAND ""
  BUILD_BYPRODUCTS ${RW_WIN64_BINARY_DIR}/RockingWall.dll ${RW_WIN64_BINARY_DIR}/Diaphragm.dll
                   ${RW_WIN64_BINARY_DIR}/Building.dll ${RW_WIN64_BINARY_DIR}/BuildingWithWalls.dll)
message(STATUS "Windows binaries: on (${RW_MINGW_GCC})")

if(NOT RW_BUILD_TESTS)
  return()
endif()

# ---- tests ----------------------------------------------------------------------------------
set(_rw_win64_tests ${CMAKE_SOURCE_DIR}/tests/win64)

# Without wine (wine64) the tests that run Windows code are skipped (ctest return code 77 with a
# message); the check of the DLLs' imports and exports needs no wine and always runs.
find_program(RW_WINE64 NAMES wine64 PATHS /usr/lib/wine /usr/lib64/wine)
set(RW_WINEPREFIX ${RW_WIN64_BINARY_DIR}/wineprefix)
set(_rw_wine_env WINEPREFIX=${RW_WINEPREFIX} WINEDEBUG=-all)

# rw_wine_test(NAME EXE ARGS...): EXE (in RW_WIN64_BINARY_DIR) run under wine
function(rw_wine_test NAME EXE)
  if(RW_WINE64)
    add_test(NAME ${NAME} COMMAND ${CMAKE_COMMAND} -E env ${_rw_wine_env} ${RW_WINE64} ${RW_WIN64_BINARY_DIR}/${EXE} ${ARGN})
    set_tests_properties(${NAME} PROPERTIES FIXTURES_REQUIRED wine_prefix)
  else()
    add_test(NAME ${NAME} COMMAND sh -c "echo 'SKIPPED: wine64 not found (Debian: apt-get install wine64); ${EXE} not run'; exit 77")
    set_tests_properties(${NAME} PROPERTIES SKIP_RETURN_CODE 77)
  endif()
endfunction()

if(RW_WINE64)
  # the first start of wine creates its prefix (slow): once, before the tests that use it
  add_test(NAME win64_wine_prefix COMMAND ${CMAKE_COMMAND} -E env ${_rw_wine_env} ${RW_WINE64} wineboot --init)
  set_tests_properties(win64_wine_prefix PROPERTIES FIXTURES_SETUP wine_prefix)
endif()

rw_wine_test(win64_test_fmi2 test_fmi2.exe)
rw_wine_test(win64_test_fmi2_bad_input test_fmi2_bad_input.exe)
rw_wine_test(win64_test_cosim_without_cvode_rw test_cosim_without_cvode_rw.exe)
rw_wine_test(win64_test_cosim_without_cvode_dg test_cosim_without_cvode_dg.exe)
rw_wine_test(win64_test_cosim_without_cvode_bd test_cosim_without_cvode_bd.exe)
rw_wine_test(win64_test_fmu_state_dg test_fmu_state_dg.exe)
rw_wine_test(win64_test_engine test_engine.exe)
rw_wine_test(win64_test_physics_dynamics test_physics_dynamics.exe ${CMAKE_BINARY_DIR}/tests/c/derive_equations.json)
set_tests_properties(win64_test_physics_dynamics PROPERTIES FIXTURES_REQUIRED "wine_prefix;derive_json")
foreach(_unit hinge_laws indicators events rigid_tie)
  rw_wine_test(win64_test_physics_${_unit} test_physics_${_unit}.exe)
endforeach()

# The packaged FMUs hold binaries/win64/NAME.dll that imports only Windows system DLLs and
# exports exactly the functions the linux64 binary exports (the fmi2 API).
find_program(RW_MINGW_OBJDUMP x86_64-w64-mingw32-objdump REQUIRED)
foreach(_name RockingWall Diaphragm Building BuildingWithWalls)
  add_test(NAME win64_binary_${_name}
    COMMAND ${CMAKE_COMMAND} -DFMU=${CMAKE_BINARY_DIR}/${_name}.fmu -DNAME=${_name}
            -DOBJDUMP=${RW_MINGW_OBJDUMP} -DNM=${CMAKE_NM} -DWORK=${RW_WIN64_BINARY_DIR}/check_${_name}
            -P ${_rw_win64_tests}/check_win64_binary.cmake)
endforeach()

# The packaged RockingWall.dll loaded under wine (LoadLibrary) and the packaged RockingWall.so
# loaded on Linux (dlopen) by the same runner give the same free-rocking results, ME and CS.
add_executable(fmu_binary_runner ${_rw_win64_tests}/fmu_binary_runner.c)
target_include_directories(fmu_binary_runner PRIVATE ${FMI2_HEADERS_DIR} ${CMAKE_SOURCE_DIR}/fmu_src/models/RockingWall
                           ${CMAKE_SOURCE_DIR}/fmu_src/wall ${CMAKE_SOURCE_DIR}/fmu_src/platform)
target_compile_definitions(fmu_binary_runner PRIVATE _POSIX_C_SOURCE=200809L)
target_link_libraries(fmu_binary_runner PRIVATE ${CMAKE_DL_LIBS} m)
if(RW_WINE64)
  add_test(NAME win64_dll_matches_linux64
    COMMAND ${CMAKE_COMMAND} -DFMU=${CMAKE_BINARY_DIR}/RockingWall.fmu -DWORK=${RW_WIN64_BINARY_DIR}/compare
            -DLINUX_RUNNER=$<TARGET_FILE:fmu_binary_runner> -DWIN_RUNNER=${RW_WIN64_BINARY_DIR}/fmu_binary_runner.exe
            -DWINE=${RW_WINE64} -DWINEPREFIX=${RW_WINEPREFIX}
            -P ${_rw_win64_tests}/compare_binaries.cmake)
  set_tests_properties(win64_dll_matches_linux64 PROPERTIES FIXTURES_REQUIRED wine_prefix)
else()
  rw_wine_test(win64_dll_matches_linux64 fmu_binary_runner.exe)
endif()
