/* fmi2sim's output files and cleanup registry (host/output_file.c, host/cleanup.c):
 * finding 1 (a failed write is reported, never a cut file left in place), finding 8 (an existing
 * output survives a failed run; a symlink stays a symlink) and finding 9 (what is registered is
 * removed, what is forgotten is not). Works in a fresh folder under TMPDIR. */
#define _XOPEN_SOURCE 700
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "cleanup.h"
#include "output_file.h"

static char dir[4096];

static const char *in_dir(const char *name)
{
    static char path[2][8192];
    static int k;
    k = !k;
    snprintf(path[k], sizeof path[k], "%s/%s", dir, name);
    return path[k];
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
}

static int file_is(const char *path, const char *text)
{
    char buf[256] = {0};
    FILE *f = fopen(path, "r");
    size_t got;
    if (!f) return 0;
    got = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    return got == strlen(text) && memcmp(buf, text, got) == 0;
}

static int entries_in_dir(void)
{
    DIR *d = opendir(dir);
    int count = 0;
    for (struct dirent *e; (e = readdir(d));) count += strcmp(e->d_name, ".") && strcmp(e->d_name, "..");
    closedir(d);
    return count;
}

static void test_finding01_commit_replaces_and_leaves_no_temporary(void)
{
    output_file o;
    char err[512];
    write_text(in_dir("out.csv"), "old\n");
    CHECK(output_open(&o, in_dir("out.csv"), err, sizeof err) == 0, "%s", err);
    CHECK(output_printf(&o, "time,x\n%d,%d\n", 0, 1) == 0, "printf");
    CHECK(file_is(in_dir("out.csv"), "old\n"), "the old file must stay until the commit");
    CHECK(output_commit(&o, err, sizeof err) == 0, "%s", err);
    CHECK(file_is(in_dir("out.csv"), "time,x\n0,1\n"), "committed content");
    CHECK(entries_in_dir() == 1, "a temporary file was left behind");
}

static void test_finding01_full_device_fails_the_commit(void)
{
    output_file o;
    char err[512] = "";
    int failed_write = 0;
    if (access("/dev/full", W_OK) != 0) return;
    CHECK(output_open(&o, "/dev/full", err, sizeof err) == 0, "%s", err);
    for (int i = 0; i < 10000; i++) failed_write |= output_printf(&o, "%d,0.123456789\n", i) != 0;
    CHECK(failed_write, "writes to /dev/full must fail once the buffer is flushed");
    CHECK(output_commit(&o, err, sizeof err) != 0 && strstr(err, "/dev/full") && strstr(err, "No space left"),
          "commit must report ENOSPC with the name: '%s'", err);
}

static void test_finding08_discard_keeps_the_existing_output(void)
{
    output_file o;
    char err[512];
    write_text(in_dir("keep.csv"), "precious\n");
    CHECK(output_open(&o, in_dir("keep.csv"), err, sizeof err) == 0, "%s", err);
    output_printf(&o, "half a row,");
    output_discard(&o);
    output_discard(&o); /* twice is harmless */
    CHECK(file_is(in_dir("keep.csv"), "precious\n"), "a discarded run must not touch the old file");
    CHECK(entries_in_dir() == 2, "a temporary file was left behind");
}

static void test_finding08_symlink_stays_a_symlink(void)
{
    output_file o;
    char err[512];
    struct stat st;
    write_text(in_dir("target.csv"), "old\n");
    CHECK(symlink(in_dir("target.csv"), in_dir("link.csv")) == 0, "symlink");
    CHECK(output_open(&o, in_dir("link.csv"), err, sizeof err) == 0, "%s", err);
    output_printf(&o, "new\n");
    CHECK(output_commit(&o, err, sizeof err) == 0, "%s", err);
    CHECK(lstat(in_dir("link.csv"), &st) == 0 && S_ISLNK(st.st_mode), "the link must stay a link");
    CHECK(file_is(in_dir("target.csv"), "new\n"), "the target is written");
}

static void test_finding09_registry_removes_what_it_holds(void)
{
    char sub[8192];
    snprintf(sub, sizeof sub, "%s", in_dir("unpacked"));
    CHECK(mkdir(sub, 0700) == 0, "mkdir");
    CHECK(cleanup_push(sub, 1) == 0, "push folder");
    write_text(in_dir("unpacked/a.xml"), "x");
    CHECK(cleanup_push(in_dir("unpacked/a.xml"), 0) == 0, "push file");
    write_text(in_dir("renamed.csv"), "x");
    CHECK(cleanup_push(in_dir("renamed.csv"), 0) == 0, "push file");
    cleanup_forget(in_dir("renamed.csv")); /* renamed into place by its owner: must stay */
    cleanup_all();
    CHECK(access(in_dir("unpacked"), F_OK) != 0, "the folder must be gone");
    CHECK(access(in_dir("renamed.csv"), F_OK) == 0, "a forgotten file must stay");
    unlink(in_dir("renamed.csv"));
}

int main(void)
{
    const char *tmp = getenv("TMPDIR");
    snprintf(dir, sizeof dir, "%s/test_host_files_XXXXXX", tmp && *tmp ? tmp : "/tmp");
    if (!mkdtemp(dir)) { perror("mkdtemp"); return 1; }
    test_finding01_commit_replaces_and_leaves_no_temporary();
    test_finding01_full_device_fails_the_commit();
    test_finding08_discard_keeps_the_existing_output();
    test_finding08_symlink_stays_a_symlink();
    test_finding09_registry_removes_what_it_holds();
    unlink(in_dir("out.csv")); unlink(in_dir("keep.csv")); unlink(in_dir("link.csv")); unlink(in_dir("target.csv"));
    rmdir(dir);
    printf("%d checks, %d failures\n", checks, failures);
    return failures ? 1 : 0;
}
