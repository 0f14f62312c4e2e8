/* The file holding libsoak's code, for finding what ships beside it (the
 * I/O modules, the data folder). Private to the core layer. */
#ifndef SOAK_SELF_PATH_H
#define SOAK_SELF_PATH_H

#include <stddef.h>

/* The program file that holds libsoak's code according to /proc/self/maps
 * (it names the executable also when the program was started through an
 * explicit loader, `ld-linux.so ... soak`, where /proc/self/exe names the
 * loader), else /proc/self/exe; "" when neither is known. */
void soak_self_file(char *path, size_t n);

/* The folder of /proc/self/exe ("" if unknown). */
void soak_self_exe_dir(char *dir, size_t n);

/* Cuts path after its last '/' (keeps "/" for a file in the root): its
 * folder; "" when path holds no '/'. */
void soak_path_dirname(char *path);

#endif
