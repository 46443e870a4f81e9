# Cross-compiling for 64-bit Windows with Debian's mingw-w64 (package mingw-w64): the FMUs'
# binaries/win64 DLLs and the Windows builds of the C tests (cmake/windows.cmake).
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(RW_MINGW_TRIPLET x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${RW_MINGW_TRIPLET}-gcc)
set(CMAKE_RC_COMPILER ${RW_MINGW_TRIPLET}-windres)
set(CMAKE_FIND_ROOT_PATH /usr/${RW_MINGW_TRIPLET})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
