/* FMU_SYMBOL(name): the name of an external symbol of an FMU. When the FMU is built from its
 * sources with -DFMI2_FUNCTION_PREFIX=Name_ (FMI 2.0) or -DFMI3_FUNCTION_PREFIX=Name_ (FMI 3.0),
 * how importers combine source-code FMUs in one binary, every external symbol carries the prefix,
 * not only the fmi2 / fmi3 functions, so that two FMUs of this repository link into one binary. */
#ifndef FMU_SYMBOL_H
#define FMU_SYMBOL_H

#if defined(FMI2_FUNCTION_PREFIX)
#define FMU_SYMBOL_PREFIX FMI2_FUNCTION_PREFIX
#elif defined(FMI3_FUNCTION_PREFIX)
#define FMU_SYMBOL_PREFIX FMI3_FUNCTION_PREFIX
#endif

#ifdef FMU_SYMBOL_PREFIX
#define FMU_SYMBOL_PASTE_(a, b) a##b
#define FMU_SYMBOL_PASTE(a, b) FMU_SYMBOL_PASTE_(a, b)
#define FMU_SYMBOL(name) FMU_SYMBOL_PASTE(FMU_SYMBOL_PREFIX, name)
#else
#define FMU_SYMBOL(name) name
#endif

#endif
