/*
 * replay_main.c - a main() for a fuzz harness without libFuzzer: the ctest
 * replay of the saved inputs (fuzz/replay.cmake).
 *
 *     replay_<harness> DIR...
 *
 * Calls LLVMFuzzerTestOneInput once on the contents of every regular file of
 * each DIR (hidden files skipped), in name order; each input is in a heap
 * block of exactly its size, as libFuzzer gives it. The directories are
 * listed when the program runs, so a reproducer copied into
 * fuzz/regressions/<harness>/ is replayed by the next ctest run. A harness
 * reports a broken invariant by aborting; this program fails as well when a
 * DIR cannot be read or when no input was found at all.
 */
#define _POSIX_C_SOURCE 200809L

#include <dirent.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int by_name(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* The whole file at path in *data (malloc'd, at least 1 byte), its size in *n. */
static int read_file(const char *path, uint8_t **data, size_t *n)
{
    FILE *f = fopen(path, "rb");
    size_t cap = 4096, len = 0, got;
    uint8_t *buf = (uint8_t *)malloc(cap);
    if (f == NULL || buf == NULL) {
        if (f != NULL) {
            (void)fclose(f);
        }
        free(buf);
        return -1;
    }
    while ((got = fread(buf + len, 1, cap - len, f)) > 0u) {
        len += got;
        if (len == cap) {
            uint8_t *more = (uint8_t *)realloc(buf, cap * 2u);
            if (more == NULL) {
                free(buf);
                (void)fclose(f);
                return -1;
            }
            buf = more;
            cap *= 2u;
        }
    }
    if (ferror(f) || fclose(f) != 0) {
        free(buf);
        return -1;
    }
    *data = buf;
    *n = len;
    return 0;
}

/* Replay every regular file of dir; returns the number replayed, or -1. */
static long replay_dir(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *ent;
    char **names = NULL;
    size_t nnames = 0, cap = 0, i;
    long done = 0;
    if (d == NULL) {
        fprintf(stderr, "replay: cannot open directory %s\n", dir);
        return -1;
    }
    while ((ent = readdir(d)) != NULL) {
        if (ent->d_name[0] == '.') {
            continue; /* ., .. and hidden files */
        }
        if (nnames == cap) {
            char **more;
            cap = (cap == 0u) ? 64u : cap * 2u;
            more = (char **)realloc(names, cap * sizeof(*names));
            if (more == NULL) {
                fprintf(stderr, "replay: out of memory\n");
                exit(1);
            }
            names = more;
        }
        names[nnames] = (char *)malloc(strlen(ent->d_name) + 1u);
        if (names[nnames] == NULL) {
            fprintf(stderr, "replay: out of memory\n");
            exit(1);
        }
        strcpy(names[nnames], ent->d_name);
        nnames++;
    }
    (void)closedir(d);
    if (nnames > 1u) {
        qsort(names, nnames, sizeof(*names), by_name);
    }
    for (i = 0; i < nnames; i++) {
        char path[4096];
        struct stat st;
        uint8_t *data, *exact;
        size_t n;
        if ((size_t)snprintf(path, sizeof(path), "%s/%s", dir, names[i]) >= sizeof(path) || stat(path, &st) != 0) {
            fprintf(stderr, "replay: cannot read %s/%s\n", dir, names[i]);
            exit(1);
        }
        free(names[i]);
        if (!S_ISREG(st.st_mode)) {
            continue;
        }
        if (read_file(path, &data, &n) != 0) {
            fprintf(stderr, "replay: cannot read %s\n", path);
            exit(1);
        }
        /* exactly n bytes, so that ASan (XFGCU_SANITIZE) catches a read past the input */
        exact = (uint8_t *)malloc((n > 0u) ? n : 1u);
        if (exact == NULL) {
            fprintf(stderr, "replay: out of memory\n");
            exit(1);
        }
        if (n > 0u) {
            memcpy(exact, data, n);
        }
        free(data);
        fprintf(stderr, "replay: %s (%zu bytes)\n", path, n);
        (void)LLVMFuzzerTestOneInput(exact, n);
        free(exact);
        done++;
    }
    free(names);
    return done;
}

int main(int argc, char **argv)
{
    long total = 0;
    int i;
    if (argc < 2) {
        fprintf(stderr, "usage: %s DIR...\n", argv[0]);
        return 2;
    }
    for (i = 1; i < argc; i++) {
        long n = replay_dir(argv[i]);
        if (n < 0) {
            return 1;
        }
        total += n;
    }
    if (total == 0) {
        fprintf(stderr, "replay: no input found\n");
        return 1;
    }
    printf("replay: %ld inputs, no violated invariant\n", total);
    return 0;
}
