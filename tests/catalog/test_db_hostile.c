/* Hostile input: broken CSV files (an unterminated quote, a 10 MB line, binary junk, an empty
 * file, zero bytes, bad UTF-8, semicolons, folders) give a clear error naming the file and the
 * line, never a crash; thousands of random mutations of a good file import or fail cleanly and
 * leave a consistent database; search texts full of FTS5 syntax are only words. */
#include "test_db_util.h"

#define GOOD                                                                                       \
    "manufacturer,article,gtin,category,series,name,width_mm,depth_mm,height_mm,list_price,"       \
    "variant_code,variant_name,diffuse,reflectivity,glossiness,blend\n"                            \
    "Hostile,H-1,4006381333931,taps_mixers,Uno,\"Uno mixer, chrome\",50,135,165,149.00,CP,"        \
    "Chrome,0.05 0.05 0.05,0.8,0.9,mix\n"                                                          \
    "Hostile,H-1,4006381333931,taps_mixers,Uno,\"Uno mixer, chrome\",50,135,165,149.00,BM,"        \
    "Black,0.03 0.03 0.03,0.04,0.3,fresnel\n"                                                      \
    "Hostile,H-2,,basins,Uno,Uno basin,600,550,175,259.00,WH,White,0.9 0.9 0.9,0.1,0.6,fresnel\n"

/* Imports data under `name` and checks the result code, that the message starts with the
 * file's name and holds every '|'-separated piece of needles, and that a failure changed
 * nothing. */
static void expect(cat_db *db, const char *name, const void *data, size_t size, cat_db_result code,
                   long line, const char *needles)
{
    const char *path = write_file(name, data, size);
    cat_db_stats before, after;
    cat_db_get_stats(db, &before, NULL, 0);
    cat_import_report rep;
    char err[4096] = "";
    cat_db_result r = cat_import_csv(db, path, NULL, &rep, err, sizeof err);
    int ok = r == code && !strncmp(err, path, strlen(path));
    char pieces[512];
    snprintf(pieces, sizeof pieces, "%s", needles);
    for (char *p = strtok(pieces, "|"); p; p = strtok(NULL, "|"))
        ok &= strstr(err, p) != NULL;
    if (line > 0)
        ok &= rep.problems_kept > 0 && rep.problems[0].line == line;
    CHECK_MSG(ok, "%s: expected %s (line %ld) with \"%s\", got %s: %s", name,
              cat_db_result_name(code), line, needles, cat_db_result_name(r), err);
    cat_import_report_free(&rep);
    cat_db_get_stats(db, &after, NULL, 0);
    CHECK(after.products == before.products && after.variants == before.variants);
}

static void test_broken_files(cat_db *db)
{
    static const char unterminated[] = "manufacturer,article,name\nA,\"A-1,x\nB,B-1,y\n";
    expect(db, "unterminated.csv", unterminated, strlen(unterminated), CAT_DB_ERR_PARSE, 2,
           "unterminated.csv:2|never closed|nothing was imported");

    static const char stray[] = "manufacturer,article,name\nA,\"A-1\"x,y\n";
    expect(db, "stray.csv", stray, strlen(stray), CAT_DB_ERR_PARSE, 2,
           "stray.csv:2|after the closing quote");

    /* A 10 MB line, with and without commas. */
    size_t big = 10u << 20;
    char *line = malloc(big + 64);
    int n = snprintf(line, 64, "manufacturer,article,name\n");
    memset(line + n, 'x', big);
    memcpy(line + n + big, "\n", 2);
    expect(db, "long-line.csv", line, n + big + 1, CAT_DB_ERR_TOO_LARGE, 2,
           "long-line.csv:2|longer than 65536 bytes");
    for (size_t i = (size_t)n; i < (size_t)n + big; i += 100)
        line[i] = ',';
    expect(db, "many-fields.csv", line, n + big + 1, CAT_DB_ERR_TOO_LARGE, 2,
           "many-fields.csv:2|more than 64 fields");
    for (size_t i = (size_t)n; i < (size_t)n + big; i += 100)
        line[i] = 'y';
    line[n] = '"';
    line[n + big - 1] = '"';
    expect(db, "long-quoted.csv", line, n + big + 1, CAT_DB_ERR_TOO_LARGE, 2,
           "long-quoted.csv:2|longer than 65536 bytes");
    free(line);

    /* Binary junk: deterministic bytes of every value. */
    unsigned char junk[1 << 16];
    unsigned x = 2463534242u;
    for (size_t i = 0; i < sizeof junk; i++) {
        x ^= x << 13, x ^= x >> 17, x ^= x << 5;
        junk[i] = (unsigned char)x;
    }
    const char *path = write_file("junk.csv", junk, sizeof junk);
    cat_import_report rep;
    char err[2048];
    cat_db_result r = cat_import_csv(db, path, NULL, &rep, err, sizeof err);
    CHECK_MSG(r != CAT_DB_OK && !strncmp(err, path, strlen(path)), "%s", err);
    cat_import_report_free(&rep);

    expect(db, "empty.csv", "", 0, CAT_DB_ERR_PARSE, 1, "empty.csv:1|the file is empty");
    expect(db, "blank.csv", "\n\r\n\n", 4, CAT_DB_ERR_PARSE, 1, "the file is empty");
    expect(db, "bom-only.csv", "\xEF\xBB\xBF", 3, CAT_DB_ERR_PARSE, 1, "the file is empty");

    static const char semicolons[] = "manufacturer;article;name\nA;A-1;x\n";
    expect(db, "semicolons.csv", semicolons, strlen(semicolons), CAT_DB_ERR_PARSE, 1,
           "semicolons|comma-separated");
    static const char unknown[] = "manufacturer,article,colour,name,name\nA,A-1,red,x,y\n";
    expect(db, "columns.csv", unknown, strlen(unknown), CAT_DB_ERR_PARSE, 1,
           "unknown column \"colour\"");
    static const char no_key[] = "manufacturer,name,variant_name\nA,x,y\n";
    expect(db, "no-key.csv", no_key, strlen(no_key), CAT_DB_ERR_PARSE, 1,
           "lacks the column article");

    static const char zero[] = "manufacturer,article,category,name,width_mm,depth_mm,height_mm,"
                               "list_price\nA,A-\0001,basins,x,1,1,1,1.00\n";
    expect(db, "zero.csv", zero, sizeof zero - 1, CAT_DB_ERR_INVALID, 2,
           "zero.csv:2|column article|zero byte");
    static const char latin1[] = "manufacturer,article,category,name,width_mm,depth_mm,height_mm,"
                                 "list_price\nM\xFC"
                                 "ller,A-1,basins,x,1,1,1,1.00\n";
    expect(db, "latin1.csv", latin1, strlen(latin1), CAT_DB_ERR_INVALID, 2,
           "column manufacturer|not valid UTF-8");
    static const char overlong[] = "manufacturer,article,category,name,width_mm,depth_mm,"
                                   "height_mm,list_price\nM,A-1,basins,\xC0\xAF,1,1,1,1.00\n";
    expect(db, "overlong.csv", overlong, strlen(overlong), CAT_DB_ERR_INVALID, 2,
           "column name|not valid UTF-8");

    /* Numbers that are not: every one a problem of its own, all reported. */
    static const char numbers[] =
        "manufacturer,article,category,name,width_mm,depth_mm,height_mm,list_price\n"
        "N,1,basins,x,0x10,1,1,1.00\n"
        "N,2,basins,x,1,-0,1,1.00\n"
        "N,3,basins,x,1,1,Infinity,1.00\n"
        "N,4,basins,x,1,1,1,999999999999\n"
        "N,5,basins,x,1e-400,1,1,.5\n"
        "N,6,basins,x,1,1,1,NaN\n"
        "N,7,basins,x,  ,1,1,1.00\n"
        "N,8,basins,x,20001,1,1,1.\n"
        "N,9,basins,x,1,1,1,100000000.01\n";
    const char *np = write_text("numbers.csv", numbers);
    CHECK(cat_import_csv(db, np, NULL, &rep, err, sizeof err) == CAT_DB_ERR_INVALID);
    print_problems(&rep);
    CHECK(has_problem(&rep, 2, "width_mm", "expected a number"));
    CHECK(has_problem(&rep, 3, "depth_mm", "greater than 0"));
    CHECK(has_problem(&rep, 4, "height_mm", "finite"));
    CHECK(has_problem(&rep, 5, "list_price", "at most 100000000.00"));
    CHECK(has_problem(&rep, 6, "width_mm", "greater than 0"));
    CHECK(has_problem(&rep, 7, "list_price", "finite"));
    CHECK(has_problem(&rep, 8, "width_mm", "is empty"));
    CHECK(has_problem(&rep, 9, "width_mm", "at most 20000"));
    /* One cent above the bound (catalog/src/db_values.c MONEY_MAX_CENTS). */
    CHECK(has_problem(&rep, 10, "list_price", "at most 100000000.00"));
    CHECK_MSG(rep.problem_count == 9, "%ld problems", rep.problem_count);
    cat_import_report_free(&rep);

    /* Files that are not files. */
    char msg[1024];
    r = cat_import_csv(db, tmp_path("no-such.csv"), NULL, &rep, msg, sizeof msg);
    CHECK_MSG(r == CAT_DB_ERR_IO && strstr(msg, "no-such.csv: cannot open"), "%s", msg);
    r = cat_import_csv(db, g_tmp, NULL, &rep, msg, sizeof msg);
    CHECK_MSG(r == CAT_DB_ERR_IO && strstr(msg, "not a regular file"), "%s", msg);
    r = cat_import_csv(db, NULL, NULL, &rep, msg, sizeof msg);
    CHECK(r == CAT_DB_ERR_INVALID);
    r = cat_import_csv_buffer(db, "nothing", NULL, 0, NULL, NULL, msg, sizeof msg);
    CHECK(r == CAT_DB_ERR_PARSE && strstr(msg, "nothing:1"));

    /* A header alone is a valid, empty import. */
    static const char header_only[] = "manufacturer,article\n";
    r = cat_import_csv_buffer(db, "header-only", header_only, strlen(header_only), NULL, &rep, msg,
                              sizeof msg);
    CHECK(r == CAT_DB_OK && rep.rows == 0);
    cat_import_report_free(&rep);
}

/* Random damage to a good file: flipped bytes, inserted quotes, commas and line breaks, cut
 * files. Each import must succeed or fail with a message that names the file. */
static void test_mutations(cat_db *db)
{
    static const char good[] = GOOD;
    size_t n = strlen(good);
    char buf[sizeof good + 64];
    unsigned x = 88172645u;
    int failures = 0, successes = 0;
    for (int round = 0; round < 1500; round++) {
        memcpy(buf, good, n + 1);
        size_t len = n;
        int edits = 1 + round % 4;
        for (int e = 0; e < edits && len > 0; e++) {
            x ^= x << 13, x ^= x >> 17, x ^= x << 5;
            size_t at = x % len;
            static const char specials[] = "\",\n\r\0\xff\xc3 -.e9";
            char c = (x >> 8) % 3 ? specials[(x >> 12) % (sizeof specials - 1)] : (char)(x >> 16);
            switch ((x >> 20) % 4) {
            case 0: /* replace */
                buf[at] = c;
                break;
            case 1: /* insert */
                if (len + 1 < sizeof buf) {
                    memmove(buf + at + 1, buf + at, len - at);
                    buf[at] = c;
                    len++;
                }
                break;
            case 2: /* delete */
                memmove(buf + at, buf + at + 1, len - at - 1);
                len--;
                break;
            default: /* cut */
                len = at;
                break;
            }
        }
        char err[2048] = "";
        cat_import_report rep;
        cat_db_result r =
            cat_import_csv_buffer(db, "mutant.csv", buf, len, NULL, &rep, err, sizeof err);
        if (r == CAT_DB_OK) {
            successes++;
        } else {
            failures++;
            CHECK_MSG(!strncmp(err, "mutant.csv", 10) && rep.problem_count > 0, "round %d: %s",
                      round, err);
        }
        cat_import_report_free(&rep);
    }
    printf("mutations: %d imported, %d refused\n", successes, failures);
    CHECK(failures > 100 && successes > 10);
    CHECK(fts_consistent(cat_db_path(db)));
    CHECK(sql_int(cat_db_path(db), "SELECT count(*) FROM pragma_integrity_check "
                                   "WHERE integrity_check <> 'ok'") == 0);
}

static void test_hostile_search(cat_db *db)
{
    cat_search_hit hits[10];
    int n = -1;
    char err[1024];
    static const char *const texts[] = {
        "\"",           "\"\"",  "*",        "AND",         "OR OR", "NOT mixer",   "NEAR(a b)",
        "a:b",          "^x",    "(((",      "mixer\"*",    "-",     "' OR 1=1 --", "%_%",
        "\xe2\x82\xac", "uno *", "name:uno", "{name}: uno", "u",     "\t\n"};
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        cat_db_result r = cat_search(db, texts[i], NULL, 10, hits, &n, err, sizeof err);
        CHECK_MSG(r == CAT_DB_OK && n >= 0 && n <= 10, "\"%s\": %s", texts[i], err);
    }
    /* Words are words: "name:uno" is not a column filter, "NOT" not an operator. */
    CHECK(cat_search(db, "NOT", NULL, 10, hits, &n, err, sizeof err) == CAT_DB_OK && n == 0);
    /* (every word must match, and no product has the word "not": none, and "NOT" is named) */
    CHECK(cat_search(db, "mixer NOT", NULL, 10, hits, &n, err, sizeof err) == CAT_DB_OK && n == 0);
    char word[16];
    CHECK(cat_search_unmatched(db, "mixer NOT", word, sizeof word, err, sizeof err) == CAT_DB_OK &&
          !strcmp(word, "NOT"));
    CHECK(cat_search(db, "mixer \"", NULL, 10, hits, &n, err, sizeof err) == CAT_DB_OK && n >= 1 &&
          strstr(hits[0].name, "mixer"));
    CHECK(cat_search(db, "Uno", NULL, 10, hits, &n, err, sizeof err) == CAT_DB_OK && n >= 1);

    char long_text[CAT_SEARCH_MAX_TEXT + 2];
    memset(long_text, 'a', sizeof long_text - 1);
    long_text[sizeof long_text - 1] = 0;
    CHECK(cat_search(db, long_text, NULL, 10, hits, &n, err, sizeof err) == CAT_DB_ERR_INVALID);
    long_text[CAT_SEARCH_MAX_TEXT] = 0; /* at the limit: fine */
    CHECK(cat_search(db, long_text, NULL, 10, hits, &n, err, sizeof err) == CAT_DB_OK);
    CHECK(cat_search(db, "M\xFCller", NULL, 10, hits, &n, err, sizeof err) == CAT_DB_ERR_INVALID);
    CHECK(strstr(err, "UTF-8") != NULL);
    CHECK(cat_search(db, "x", NULL, 0, hits, &n, err, sizeof err) == CAT_DB_ERR_INVALID);
    CHECK(cat_search(db, "x", NULL, 10001, hits, &n, err, sizeof err) == CAT_DB_ERR_INVALID);
    CHECK(cat_search(NULL, "x", NULL, 10, hits, &n, err, sizeof err) == CAT_DB_ERR_INVALID);
    CHECK(cat_search(db, NULL, NULL, 10, hits, &n, err, sizeof err) == CAT_DB_OK);
    cat_search_filter f = {.category = (cat_category)99, .max_width_mm = NAN};
    CHECK(cat_search(db, "uno", &f, 10, hits, &n, err, sizeof err) == CAT_DB_OK);

    cat_product p;
    CHECK(cat_product_find(db, NULL, "no-such-article", &p, err, sizeof err) ==
          CAT_DB_ERR_NOT_FOUND);
    CHECK(strstr(err, "no-such-article") != NULL);
    CHECK(cat_product_get(db, -5, &p, err, sizeof err) == CAT_DB_ERR_NOT_FOUND);
}

static void test_ambiguous(cat_db *db)
{
    static const char two[] = "manufacturer,article,category,name,width_mm,depth_mm,height_mm,"
                              "list_price\nFirst,SAME-1,accessories,a,1,1,1,1.00\n"
                              "Second,SAME-1,accessories,b,1,1,1,1.00\n";
    cat_import_report rep;
    char err[1024];
    CHECK(cat_import_csv_buffer(db, "two.csv", two, strlen(two), NULL, &rep, err, sizeof err) ==
          CAT_DB_OK);
    cat_import_report_free(&rep);
    cat_product p;
    CHECK(cat_product_find(db, NULL, "same-1", &p, err, sizeof err) == CAT_DB_ERR_AMBIGUOUS);
    CHECK(strstr(err, "First") && strstr(err, "Second"));
    CHECK(cat_product_find(db, "second", "same-1", &p, err, sizeof err) == CAT_DB_OK);
    CHECK(!strcmp(p.name, "b"));
    cat_product_free(&p);
}

int main(void)
{
    tmp_make();
    cat_db *db = open_catalog("hostile.sqlite", 0);
    cat_import_report rep;
    char err[1024];
    static const char good[] = GOOD;
    CHECK(cat_import_csv_buffer(db, "good.csv", good, strlen(good), NULL, &rep, err, sizeof err) ==
          CAT_DB_OK);
    cat_import_report_free(&rep);
    test_broken_files(db);
    test_mutations(db);
    test_hostile_search(db);
    test_ambiguous(db);
    cat_db_close(db);
    tmp_remove();
    return check_report("test_db_hostile");
}
