/* The fuzz corpus replay for builds without libFuzzer: app_project_parse over every file in
 * tests/data/projects/ and a few hundred deterministic mutations of each (byte flips,
 * interesting bytes, truncations, deleted and duplicated slices). Passes when nothing
 * crashes (ASan/UBSan builds make that strict), every failure has a message naming the file,
 * and whatever parses can be written and read back. */
#include "test_util.h"

#include "app/project/project.h"

#define DATA TESSERA_PROJECT_TEST_DATA
#define MUTATIONS_PER_FILE 70

static unsigned long long rng_state = 0x9E3779B97F4A7C15ull;

static unsigned rng(void) /* xorshift64*: the same sequence on every run */
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (unsigned)((rng_state * 2685821657736338717ull) >> 32);
}

static char *tmp_dir;
static int parsed_ok, parsed_err;

static void parse_one(const char *data, size_t len)
{
    char err[1024] = "";
    app_project p;
    /* the mutated text pretends to live next to the fixtures, so references can resolve */
    app_result r = app_project_parse(data, len, DATA "/mutant.json", &p, err, sizeof err);
    if (r != APP_OK) {
        parsed_err++;
        CHECK_MSG(tu_contains(err, DATA "/mutant.json: "), "%s", err);
        CHECK(p.materials == NULL && p.objects == NULL && p.cameras == NULL);
        return;
    }
    parsed_ok++;
    char out[4096];
    snprintf(out, sizeof out, "%s/out.json", tmp_dir);
    r = app_project_write(out, &p, err, sizeof err);
    CHECK_MSG(r == APP_OK, "%s", err);
    if (r == APP_OK) {
        app_project q;
        r = app_project_read(out, &q, err, sizeof err);
        CHECK_MSG(r == APP_OK, "%s", err);
        if (r == APP_OK)
            app_project_free(&q);
    }
    app_project_free(&p);
}

static const char interesting[] = {'{', '}',  '[',  ']',  '"', ',', ':', '0', '-',    'e',
                                   '.', '\\', '\0', '\n', ' ', '9', 'n', 't', '\xff', '\x80'};

static void mutate_and_parse(const char *orig, size_t len)
{
    char *buf = malloc(len * 2 + 16);
    if (!buf)
        return;
    for (int m = 0; m < MUTATIONS_PER_FILE; m++) {
        memcpy(buf, orig, len);
        size_t n = len;
        size_t at = len ? rng() % len : 0;
        switch (m % 7) {
        case 0: /* flip bits */
            if (n)
                buf[at] ^= (char)(1u << (rng() % 8));
            break;
        case 1: /* an interesting byte */
            if (n)
                buf[at] = interesting[rng() % sizeof interesting];
            break;
        case 2: /* truncate */
            n = at;
            break;
        case 3: { /* delete a slice */
            size_t k = n > at ? rng() % (n - at) % 64 : 0;
            memmove(buf + at, buf + at + k, n - at - k);
            n -= k;
            break;
        }
        case 4: { /* duplicate a slice */
            size_t k = n > at ? (rng() % (n - at)) % 64 : 0;
            memmove(buf + at + k, buf + at, n - at);
            n += k;
            break;
        }
        case 5: { /* another digit or sign, so that more mutants stay valid JSON */
            for (size_t k = 0; k < n; k++) {
                size_t i = (at + k) % n;
                if (buf[i] >= '0' && buf[i] <= '9') {
                    buf[i] = "0123456789-"[rng() % 11];
                    break;
                }
            }
            break;
        }
        default: /* several flips */
            for (int i = 0; i < 4 && n; i++)
                buf[rng() % n] = interesting[rng() % sizeof interesting];
            break;
        }
        parse_one(buf, n);
    }
    free(buf);
}

int main(void)
{
    tmp_dir = tu_make_temp_dir();
    CHECK(tmp_dir != NULL);
    DIR *d = opendir(DATA);
    CHECK(d != NULL);
    int files = 0;
    if (d && tmp_dir) {
        struct dirent *e;
        while ((e = readdir(d)) != NULL) {
            char path[4096];
            snprintf(path, sizeof path, "%s/%s", DATA, e->d_name);
            struct stat st;
            if (stat(path, &st) != 0 || !S_ISREG(st.st_mode))
                continue;
            size_t len = 0;
            char *text = tu_read_file(path, &len);
            CHECK(text != NULL);
            if (!text)
                continue;
            files++;
            parse_one(text, len);
            mutate_and_parse(text, len);
            free(text);
        }
        closedir(d);
    }
    /* plain noise */
    for (int i = 0; i < 50; i++) {
        char noise[256];
        size_t n = rng() % sizeof noise;
        for (size_t k = 0; k < n; k++)
            noise[k] = interesting[rng() % sizeof interesting];
        parse_one(noise, n);
    }
    CHECK(files >= 5);
    CHECK(parsed_ok > 0 && parsed_err > 0);
    printf("project_fuzz_replay: %d files, %d inputs parsed, %d refused\n", files, parsed_ok,
           parsed_err);
    if (tmp_dir) {
        tu_remove_tree(tmp_dir);
        free(tmp_dir);
    }
    return check_report("project_fuzz_replay");
}
