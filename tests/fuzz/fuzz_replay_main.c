/* A main() for the fuzz targets in tests/fuzz in builds without libFuzzer (GCC, the CI's
 * compiler): replays a corpus, then deterministic mutations of it
 * (bit flips, byte sweeps with interesting values, truncations, duplicated and dropped runs)
 * until a time budget is spent, so the targets run briefly in every CI build, under ASan and
 * UBSan in the sanitizer build.
 *   fuzz_gltf [--seconds S] FILE_OR_FOLDER...
 * A crash, a sanitizer report or an abort() in the target fails the run, and the input that
 * did it is saved as crash-replay-input in the current folder (sanitizer reports too when
 * ASAN_OPTIONS / UBSAN_OPTIONS hold abort_on_error=1, as ctest sets them). */
#define _XOPEN_SOURCE 700
#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

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

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TESSERA_HAS_ASAN 1
#endif
#endif
#ifndef TESSERA_HAS_ASAN
#define TESSERA_HAS_ASAN 0
#endif

static double g_slow_seconds = 1.0;
static const uint8_t *g_current;
static size_t g_current_size;

/* Async-signal-safe: open, write and close only. */
static void save_current_input(int sig)
{
    static const char msg[] = "fuzz replay: the input that failed is in crash-replay-input\n";
    int fd = open("crash-replay-input", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        size_t done = 0;
        while (done < g_current_size) {
            ssize_t n = write(fd, g_current + done, g_current_size - done);
            if (n <= 0)
                break;
            done += (size_t)n;
        }
        close(fd);
        if (write(2, msg, sizeof msg - 1) < 0) {
            /* nothing more to say */
        }
    }
    signal(sig, SIG_DFL);
    raise(sig);
}

static void run_one(const uint8_t *data, size_t size)
{
    g_current = data;
    g_current_size = size;
    LLVMFuzzerTestOneInput(data, size);
}

/* A slow input is kept as slow-replay-input-N in the current folder, not a failure: the time
 * depends on the machine's load. */
static void report_slow(const char *seed, const unsigned char *data, size_t size, double s)
{
    static int count;
    char name[64];
    snprintf(name, sizeof name, "slow-replay-input-%d", count++);
    FILE *f = fopen(name, "wb");
    if (f) {
        fwrite(data, 1, size, f);
        fclose(f);
    }
    fprintf(stderr, "fuzz replay: a mutation of %s took %.1f s (kept as %s)\n", seed, s, name);
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
#if defined(__SANITIZE_ADDRESS__) || TESSERA_HAS_ASAN
    /* ASan reports a SIGSEGV itself (with the stack) and then aborts: keep its handler */
    static const int fatal[] = {SIGABRT};
#else
    static const int fatal[] = {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL};
#endif
    for (size_t k = 0; k < sizeof fatal / sizeof fatal[0]; k++)
        signal(fatal[k], save_current_input);
    qsort(g_files, (size_t)g_file_count, sizeof *g_files, by_name);
    double start = now_s();
    long runs = 0;
    run_one((const uint8_t *)"", 0);
    for (int i = 0; i < g_file_count; i++) {
        size_t size = 0;
        unsigned char *data = read_all(g_files[i], &size);
        if (data)
            run_one(data, size);
        free(data);
        runs++;
    }
    /* mutations, round robin over the corpus, until the budget is spent */
    unsigned char *dst = NULL;
    for (int i = 0; now_s() - start < seconds; i = (i + 1) % g_file_count) {
        size_t size = 0;
        unsigned char *data = read_all(g_files[i], &size);
        dst = data ? malloc(2 * size + 16) : NULL;
        for (int k = 0; dst && k < 16 && now_s() - start < seconds; k++) {
            size_t n = mutate(data, size, dst);
            double t0 = now_s();
            run_one(dst, n);
            runs++;
            if (now_s() - t0 > g_slow_seconds) /* worth a look: a denial of service? */
                report_slow(g_files[i], dst, n, now_s() - t0);
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
