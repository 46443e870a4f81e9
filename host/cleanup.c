/* The registry behind cleanup.h. The signal handler may run at any moment, so it only reads
 * entries that are complete (the count is raised after the entry is written, with the signals
 * blocked) and only calls unlink, rmdir, signal and raise, which are async-signal-safe. */
#include "cleanup.h"

#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* the unpacked FMU (at most 1 + FMU_MAX_ENTRIES files and their folders) and two outputs */
#define CLEANUP_SLOTS 2200

typedef struct {
    char *path; /* NULL once forgotten or removed */
    int is_dir;
} entry;

static entry entries[CLEANUP_SLOTS];
static volatile sig_atomic_t n_entries;
static const int caught[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};

static void block_signals(sigset_t *old)
{
    sigset_t set;
    sigemptyset(&set);
    for (size_t i = 0; i < sizeof caught / sizeof caught[0]; i++) sigaddset(&set, caught[i]);
    sigprocmask(SIG_BLOCK, &set, old);
}

int cleanup_push(const char *path, int is_dir)
{
    sigset_t old;
    char *copy;
    if (n_entries >= CLEANUP_SLOTS || !(copy = strdup(path))) return -1;
    block_signals(&old);
    entries[n_entries].path = copy;
    entries[n_entries].is_dir = is_dir;
    n_entries++;
    sigprocmask(SIG_SETMASK, &old, NULL);
    return 0;
}

void cleanup_forget(const char *path)
{
    sigset_t old;
    block_signals(&old);
    for (sig_atomic_t i = n_entries; i-- > 0;)
        if (entries[i].path && strcmp(entries[i].path, path) == 0) {
            free(entries[i].path);
            entries[i].path = NULL;
            break;
        }
    sigprocmask(SIG_SETMASK, &old, NULL);
}

/* async-signal-safe: unlink and rmdir only, no free */
static void remove_entries(void)
{
    for (sig_atomic_t i = n_entries; i-- > 0;)
        if (entries[i].path) {
            if (entries[i].is_dir) rmdir(entries[i].path);
            else unlink(entries[i].path);
        }
}

void cleanup_all(void)
{
    sigset_t old;
    block_signals(&old);
    remove_entries();
    for (sig_atomic_t i = 0; i < n_entries; i++) free(entries[i].path);
    n_entries = 0;
    sigprocmask(SIG_SETMASK, &old, NULL);
}

static void on_signal(int sig)
{
    remove_entries();
    signal(sig, SIG_DFL);
    raise(sig); /* delivered when the handler returns: the exit status says which signal */
}

/* an FMU that calls exit() skips main's cleanup */
static void at_exit(void)
{
    remove_entries();
}

void cleanup_install_signal_handlers(void)
{
    atexit(at_exit);
    for (size_t i = 0; i < sizeof caught / sizeof caught[0]; i++) {
        struct sigaction sa, old;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigfillset(&sa.sa_mask); /* one cleanup at a time */
        if (sigaction(caught[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN) continue; /* nohup */
        sigaction(caught[i], &sa, NULL);
    }
    signal(SIGXFSZ, SIG_IGN);
}
