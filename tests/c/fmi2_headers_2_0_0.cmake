# Writes the FMI 2.0.0 form of the FMI 2.0 headers into OUT from the 2.0.x headers in IN (fmpy's):
#   cmake -DIN=<dir> -DOUT=<dir> -P fmi2_headers_2_0_0.cmake
# No registry ships the original 2.0.0 headers (no Debian package; the PyPI packages that ship
# FMI headers carry modified ones), so the tests make them. Two differences matter to an FMU:
#  - 2.0.0 declares the five members of fmi2CallbackFunctions const (removed in 2.0.1, #216), so
#    an FMU that assigns a copy of the struct does not compile;
#  - 2.0.0 prefixes every fmi2 function name with FMI2_FUNCTION_PREFIX when it is defined, the
#    way importers combine source-code FMUs; fmpy's copy drops the prefix.
# Each edit must match exactly once, else the script fails: a changed input cannot pass silently.
function(replace_once text_var old new)
  string(FIND "${${text_var}}" "${old}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "fmi2_headers_2_0_0: '${old}' not found in the input headers (${IN})")
  endif()
  string(REPLACE "${old}" "${new}" result "${${text_var}}")
  set(${text_var} "${result}" PARENT_SCOPE)
endfunction()

file(MAKE_DIRECTORY ${OUT})
file(READ ${IN}/fmi2FunctionTypes.h types)
foreach(member "fmi2CallbackLogger         logger;" "fmi2CallbackAllocateMemory allocateMemory;"
               "fmi2CallbackFreeMemory     freeMemory;" "fmi2StepFinished           stepFinished;"
               "fmi2ComponentEnvironment   componentEnvironment;")
  replace_once(types "   ${member}" "   const ${member}")
endforeach()
file(WRITE ${OUT}/fmi2FunctionTypes.h "${types}")

file(READ ${IN}/fmi2Functions.h functions)
replace_once(functions "#define fmi2FullName(name) name"
"#ifdef FMI2_FUNCTION_PREFIX
#define fmi2Paste(a, b) a##b
#define fmi2PasteB(a, b) fmi2Paste(a, b)
#define fmi2FullName(name) fmi2PasteB(FMI2_FUNCTION_PREFIX, name)
#else
#define fmi2FullName(name) name
#endif")
file(WRITE ${OUT}/fmi2Functions.h "${functions}")
file(COPY ${IN}/fmi2TypesPlatform.h DESTINATION ${OUT})
