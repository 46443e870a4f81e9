/* Files and folders fmi2sim creates (the unpacked FMU, temporary outputs) and their removal on
 * every exit path that can be caught: normal returns call cleanup_all(); SIGINT, SIGTERM, SIGHUP
 * and SIGPIPE run the same removal inside the signal handler and then re-raise the signal. */
#ifndef FMI2SIM_CLEANUP_H
#define FMI2SIM_CLEANUP_H

/* Remember PATH (a file, or a folder when is_dir) for removal; 0, or -1 when out of slots. */
int cleanup_push(const char *path, int is_dir);
/* PATH was renamed or removed by its owner: forget it. */
void cleanup_forget(const char *path);
/* Remove everything remembered, newest first (folders must be empty by then). */
void cleanup_all(void);
/* Catch SIGINT, SIGTERM, SIGHUP, SIGPIPE (unless ignored by the parent) and exit() called from
 * inside the FMU; ignore SIGXFSZ so that a write over the file-size limit fails with EFBIG and is
 * reported like any failed write. */
void cleanup_install_signal_handlers(void);

#endif
