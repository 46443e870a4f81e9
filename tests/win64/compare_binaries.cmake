# The packaged RockingWall.dll run under wine against the packaged RockingWall.so on Linux (cmake -P,
# see cmake/windows.cmake): fmu_binary_runner (one source, built for both) loads each binary out of
# the unzipped FMU and runs free rocking through Model Exchange (explicit Euler), through
# Co-Simulation (the exact engine) and through Co-Simulation under a record the binary reads itself
# (agFile); it prints peak |s1|, peak |s2|, impacts and q1 at the end.
# The impacts must be equal and the numbers agree to REL_TOL: both binaries do the same arithmetic
# in the same order, only the C libraries' math functions may differ in the last bit.
# -DFMU= -DWORK= -DLINUX_RUNNER= -DWIN_RUNNER= -DWINE= -DWINEPREFIX=
set(REL_TOL 1e-9)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${CMAKE_COMMAND} -E tar xf ${FMU} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK}/binaries/win64/RockingWall.dll)
  message(FATAL_ERROR "${FMU} does not hold binaries/win64/RockingWall.dll")
endif()

# "peak_s1 peak_s2 impacts q1_end" of one run, as a list
function(run_binary OUT)
  execute_process(COMMAND ${ARGN} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc
                  OUTPUT_STRIP_TRAILING_WHITESPACE WORKING_DIRECTORY ${WORK})
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${ARGN} failed (${rc}): ${err}")
  endif()
  string(REGEX MATCH "[^\r\n]+$" out "${out}") # the result line (wine may print more before it)
  string(REPLACE " " ";" values "${out}")
  list(LENGTH values n)
  if(NOT n EQUAL 4)
    message(FATAL_ERROR "${ARGN} printed \"${out}\", expected 4 numbers")
  endif()
  set(${OUT} ${values} PARENT_SCOPE)
endfunction()

foreach(mode me cs csfile)
  run_binary(linux ${LINUX_RUNNER} ${WORK}/binaries/linux64/RockingWall.so ${mode})
  run_binary(windows ${CMAKE_COMMAND} -E env WINEPREFIX=${WINEPREFIX} WINEDEBUG=-all
             ${WINE} ${WIN_RUNNER} ${WORK}/binaries/win64/RockingWall.dll ${mode})
  message(STATUS "${mode}: linux64 ${linux}")
  message(STATUS "${mode}: win64   ${windows}")
  list(GET linux 2 impacts_linux)
  list(GET windows 2 impacts_windows)
  if(impacts_linux LESS 2 OR NOT impacts_linux EQUAL impacts_windows)
    message(FATAL_ERROR "${mode}: impacts linux64 ${impacts_linux}, win64 ${impacts_windows}")
  endif()
  foreach(i 0 1 3)
    list(GET linux ${i} a)
    list(GET windows ${i} b)
    # CMake has no floating-point arithmetic: the runner compares
    execute_process(COMMAND ${LINUX_RUNNER} --compare ${a} ${b} ${REL_TOL} RESULT_VARIABLE same)
    if(NOT same EQUAL 0)
      message(FATAL_ERROR "${mode}: value ${i} differs: linux64 ${a}, win64 ${b} (relative tolerance ${REL_TOL})")
    endif()
  endforeach()
endforeach()
