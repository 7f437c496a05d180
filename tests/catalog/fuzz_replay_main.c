/* A main() for the libFuzzer targets (fuzz_gltf.c, test_db_fuzz_csv.c) in builds without
 * libFuzzer (GCC, the CI's compiler): replays a corpus, then deterministic mutations of it
 * (bit flips, byte sweeps with interesting values, truncations, duplicated and dropped runs)
 * until a time budget is spent, so the targets run briefly in every CI build, under ASan and
 * UBSan in the sanitizer build.
 *   fuzz_gltf_replay [--seconds S] FILE_OR_FOLDER...
 * A crash, a sanitizer report or an abort() in the target fails the run. */
#define _XOPEN_SOURCE 700
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAX_INPUT (4u << 20) /* corpus files above 4 MiB are skipped */
#define MAX_FILES 512

static char *g_files[MAX_FILES];
static int g_file_count;

static void add_path(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0) {
        fprintf(stderr, "fuzz replay: %s: not found\n", path);
        exit(2);
    }
    if (S_ISREG(st.st_mode)) {
        if (g_file_count < MAX_FILES && st.st_size <= (off_t)MAX_INPUT)
            g_files[g_file_count++] = strdup(path);
        return;
    }
    DIR *d = opendir(path);
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.')
            continue;
        char child[4096];
        snprintf(child, sizeof child, "%s/%s", path, e->d_name);
        if (stat(child, &st) == 0 && S_ISREG(st.st_mode))
            add_path(child);
    }
    closedir(d);
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static unsigned char *read_all(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    unsigned char *buf = malloc(MAX_INPUT + 1);
    *size = buf ? fread(buf, 1, MAX_INPUT, f) : 0;
    fclose(f);
    return buf;
}

static uint32_t g_rng = 0x9E3779B9u;

static uint32_t next(void)
{
    g_rng ^= g_rng << 13; /* xorshift32: the same mutations on every run */
    g_rng ^= g_rng >> 17;
    g_rng ^= g_rng << 5;
    return g_rng;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* One mutation of src into dst (capacity 2 * size + 16); returns the new size. */
static size_t mutate(const unsigned char *src, size_t size, unsigned char *dst)
{
    static const unsigned char interesting[] = {0,   1,   0x7f, 0x80, 0xff, '"', '\\', ',', '\n',
                                                '{', '}', '[',  ']',  '9',  '-', '.',  'e'};
    memcpy(dst, src, size);
    if (size == 0)
        return 0;
    size_t at = next() % size;
    switch (next() % 6) {
    case 0: /* flip a bit */
        dst[at] ^= (unsigned char)(1u << (next() % 8));
        return size;
    case 1: /* an interesting byte */
        dst[at] = interesting[next() % sizeof interesting];
        return size;
    case 2: /* truncate */
        return at;
    case 3: { /* duplicate a run */
        size_t len = 1 + next() % 64;
        if (at + len > size)
            len = size - at;
        memmove(dst + at + len, src + at, size - at);
        memcpy(dst + at, src + at, len);
        return size + len;
    }
    case 4: { /* drop a run */
        size_t len = 1 + next() % 64;
        if (at + len > size)
            len = size - at;
        memmove(dst + at, src + at + len, size - at - len);
        return size - len;
    }
    default: /* a digit sweep: numbers become huge, negative or long */
        for (size_t i = at; i < size && i < at + 12; i++)
            if (dst[i] >= '0' && dst[i] <= '9')
                dst[i] = (unsigned char)('0' + next() % 10);
        return size;
    }
}

int main(int argc, char **argv)
{
    double seconds = 3;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--seconds") && i + 1 < argc)
            seconds = atof(argv[++i]);
        else
            add_path(argv[i]);
    }
    if (g_file_count == 0) {
        fprintf(stderr, "usage: %s [--seconds S] FILE_OR_FOLDER...\n", argv[0]);
        return 2;
    }
    qsort(g_files, (size_t)g_file_count, sizeof *g_files, by_name);
    double start = now_s();
    long runs = 0;
    LLVMFuzzerTestOneInput((const uint8_t *)"", 0);
    for (int i = 0; i < g_file_count; i++) {
        size_t size = 0;
        unsigned char *data = read_all(g_files[i], &size);
        if (data)
            LLVMFuzzerTestOneInput(data, size);
        free(data);
        runs++;
    }
    /* mutations, round robin over the corpus, until the budget is spent */
    unsigned char *dst = NULL;
    for (int i = 0; now_s() - start < seconds; i = (i + 1) % g_file_count) {
        size_t size = 0;
        unsigned char *data = read_all(g_files[i], &size);
        dst = data ? malloc(2 * size + 16) : NULL;
        for (int k = 0; dst && k < 16; k++) {
            size_t n = mutate(data, size, dst);
            LLVMFuzzerTestOneInput(dst, n);
            runs++;
        }
        free(dst);
        free(data);
    }
    printf("%ld inputs (%d corpus files, the rest mutations) in %.1f s\n", runs, g_file_count,
           now_s() - start);
    for (int i = 0; i < g_file_count; i++)
        free(g_files[i]);
    return 0;
}
