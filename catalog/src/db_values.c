/* Values of CSV cells: numbers, money, colours, texts and asset paths, each checked strictly
 * (plain decimal numbers only, no NaN or infinity, no thousands separators), and the shortest
 * text that reads back as the same number for export. The C locale is assumed (Tessera never
 * calls setlocale), so the decimal separator is the point. */
#include "db_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* The cell as it appears in a message: at most 40 bytes, bytes outside printable ASCII as '?'
 * (so a message is always clean text, whatever the file held). */
static const char *shown(const char *text, char buf[48])
{
    size_t n = strlen(text), i = 0;
    for (; i < n && i < 40; i++) {
        unsigned char ch = (unsigned char)text[i];
        buf[i] = ch < 0x20 || ch >= 0x7F ? '?' : (char)ch;
    }
    memcpy(buf + i, n > 40 ? "..." : "", n > 40 ? 4 : 1);
    return buf;
}

static const char *say(char *msg, size_t size, const char *fmt, const char *a, double x, double y)
{
    /* The format takes, in order, the shown cell (%s) and up to two numbers (%g). */
    snprintf(msg, size, fmt, a, x, y);
    return msg;
}

/* Plain decimal: [+-]digits[.digits][(e|E)[+-]digits] with at least one digit before the
 * exponent. */
static int is_decimal(const char *s)
{
    if (*s == '+' || *s == '-')
        s++;
    int digits = 0;
    while (*s >= '0' && *s <= '9')
        s++, digits++;
    if (*s == '.') {
        s++;
        while (*s >= '0' && *s <= '9')
            s++, digits++;
    }
    if (!digits)
        return 0;
    if (*s == 'e' || *s == 'E') {
        s++;
        if (*s == '+' || *s == '-')
            s++;
        if (!(*s >= '0' && *s <= '9'))
            return 0;
        while (*s >= '0' && *s <= '9')
            s++;
    }
    return *s == 0;
}

static int looks_non_finite(const char *s)
{
    if (*s == '+' || *s == '-')
        s++;
    return !strncasecmp(s, "nan", 3) || !strncasecmp(s, "inf", 3);
}

const char *catdb_parse_real(const char *text, double lo, double hi, int lo_open, double *out,
                             char *msg, size_t msg_size)
{
    char b[48];
    if (looks_non_finite(text))
        return say(msg, msg_size, "must be a finite number, got \"%s\"", shown(text, b), 0, 0);
    if (!is_decimal(text)) {
        int comma = strchr(text, ',') != NULL;
        return say(msg, msg_size,
                   comma ? "expected a number with a decimal point, got \"%s\""
                         : "expected a number, got \"%s\"",
                   shown(text, b), 0, 0);
    }
    double v = strtod(text, NULL);
    if (!isfinite(v))
        return say(msg, msg_size, "must be a finite number, got \"%s\"", shown(text, b), 0, 0);
    if (v == 0)
        v = 0; /* no negative zero */
    if ((lo_open ? !(v > lo) : !(v >= lo)) || !(v <= hi)) {
        if (lo_open)
            return say(msg, msg_size, "must be greater than %2$g and at most %3$g, got \"%1$s\"",
                       shown(text, b), lo, hi);
        return say(msg, msg_size, "must be between %2$g and %3$g, got \"%1$s\"", shown(text, b), lo,
                   hi);
    }
    *out = v;
    return NULL;
}

const char *catdb_parse_int(const char *text, long lo, long hi, long *out, char *msg,
                            size_t msg_size)
{
    char b[48];
    const char *s = text;
    if (*s == '+' || *s == '-')
        s++;
    size_t digits = strspn(s, "0123456789");
    if (!digits || s[digits])
        return say(msg, msg_size, "expected a whole number, got \"%s\"", shown(text, b), 0, 0);
    double v = strtod(text, NULL); /* exact for the small ranges used here */
    if (!(v >= (double)lo && v <= (double)hi))
        return say(msg, msg_size, "must be between %2$g and %3$g, got \"%1$s\"", shown(text, b),
                   (double)lo, (double)hi);
    *out = (long)v;
    return NULL;
}

/* 100 000 000.00: far above any bathroom product, and low enough that a quotation's quantity x
 * price, its VAT and the sum over its lines stay well inside long long cents (a price near
 * INT64_MAX would wrap the totals to a negative amount). */
#define MONEY_MAX_CENTS 10000000000LL

const char *catdb_parse_money(const char *text, int allow_zero, long long *cents, char *msg,
                              size_t msg_size)
{
    char b[48];
    const char *s = text;
    if (looks_non_finite(s))
        return say(msg, msg_size, "must be a finite amount, got \"%s\"", shown(text, b), 0, 0);
    if (*s == '-')
        return say(msg, msg_size,
                   allow_zero ? "must not be negative, got \"%s\"" : "must be positive, got \"%s\"",
                   shown(text, b), 0, 0);
    if (*s == '+')
        s++;
    long long whole = 0;
    int digits = 0;
    for (; *s >= '0' && *s <= '9'; s++, digits++) {
        whole = whole * 10 + (*s - '0');
        if (whole > MONEY_MAX_CENTS / 100)
            return say(msg, msg_size, "must be at most 100000000.00, got \"%s\"", shown(text, b), 0,
                       0);
    }
    long long frac = 0;
    int decimals = 0;
    if (*s == '.') {
        s++;
        for (; *s >= '0' && *s <= '9'; s++, decimals++) {
            if (decimals == 2)
                return say(msg, msg_size, "has more than two decimals: \"%s\"", shown(text, b), 0,
                           0);
            frac = frac * 10 + (*s - '0');
        }
    }
    if ((!digits && !decimals) || *s) {
        int comma = strchr(text, ',') != NULL;
        return say(msg, msg_size,
                   comma ? "expected an amount like 1234.50 (a decimal point, no thousands "
                           "separator), got \"%s\""
                         : "expected an amount like 1234.50, got \"%s\"",
                   shown(text, b), 0, 0);
    }
    if (decimals == 1)
        frac *= 10;
    long long v = whole * 100 + frac;
    if (v > MONEY_MAX_CENTS)
        return say(msg, msg_size, "must be at most 100000000.00, got \"%s\"", shown(text, b), 0, 0);
    if (v == 0 && !allow_zero)
        return say(msg, msg_size, "must be positive, got \"%s\"", shown(text, b), 0, 0);
    *cents = v;
    return NULL;
}

const char *catdb_parse_rgb(const char *text, double hi, double out[3], char *msg, size_t msg_size)
{
    char b[48], part[64];
    double v[3];
    const char *s = text;
    for (int k = 0; k < 4; k++) {
        while (*s == ' ' || *s == '\t')
            s++;
        size_t len = strcspn(s, " \t");
        if (k == 3) {
            if (len == 0)
                break;
            return say(msg, msg_size, "expected three numbers \"r g b\", got \"%s\"",
                       shown(text, b), 0, 0);
        }
        if (len == 0 || len >= sizeof part)
            return say(msg, msg_size, "expected three numbers \"r g b\", got \"%s\"",
                       shown(text, b), 0, 0);
        memcpy(part, s, len);
        part[len] = 0;
        s += len;
        double x;
        char inner[160];
        if (catdb_parse_real(part, 0, hi, 0, &x, inner, sizeof inner)) {
            snprintf(msg, msg_size, "component %d %s", k + 1, inner);
            return msg;
        }
        v[k] = x;
    }
    memcpy(out, v, sizeof v);
    return NULL;
}

/* Length of the UTF-8 sequence at s (at most n bytes), 0 if it is not valid: no overlong
 * forms, no surrogates, nothing above U+10FFFF (RFC 3629). */
static size_t utf8_sequence(const unsigned char *s, size_t n)
{
    unsigned char c = s[0];
    if (c < 0x80)
        return 1;
    size_t len;
    unsigned cp, min;
    if ((c & 0xE0) == 0xC0)
        len = 2, cp = c & 0x1F, min = 0x80;
    else if ((c & 0xF0) == 0xE0)
        len = 3, cp = c & 0x0F, min = 0x800;
    else if ((c & 0xF8) == 0xF0)
        len = 4, cp = c & 0x07, min = 0x10000;
    else
        return 0;
    if (len > n)
        return 0;
    for (size_t i = 1; i < len; i++) {
        if ((s[i] & 0xC0) != 0x80)
            return 0;
        cp = cp << 6 | (s[i] & 0x3F);
    }
    if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
        return 0;
    return len;
}

const char *catdb_check_text(const char *text, size_t length, size_t max_bytes, int multi_line,
                             char *msg, size_t msg_size)
{
    const unsigned char *s = (const unsigned char *)text;
    for (size_t i = 0; i < length;) {
        if (s[i] == 0) {
            snprintf(msg, msg_size, "contains a zero byte (at byte %zu)", i + 1);
            return msg;
        }
        size_t k = utf8_sequence(s + i, length - i);
        if (!k) {
            snprintf(msg, msg_size, "is not valid UTF-8 (byte %zu is 0x%02X)", i + 1, s[i]);
            return msg;
        }
        if (k == 1 && (s[i] < 0x20 || s[i] == 0x7F) &&
            !(multi_line && (s[i] == '\n' || s[i] == '\t' || s[i] == '\r'))) {
            snprintf(msg, msg_size, "contains a control character (0x%02X at byte %zu)", s[i],
                     i + 1);
            return msg;
        }
        i += k;
    }
    if (length > max_bytes) {
        snprintf(msg, msg_size, "has %zu bytes, the limit is %zu", length, max_bytes);
        return msg;
    }
    return NULL;
}

const char *catdb_check_asset_path(const char *text, char *msg, size_t msg_size)
{
    char b[48];
    if (text[0] == '/' || strchr(text, '\\') || strchr(text, ':'))
        return say(msg, msg_size,
                   "must be a relative path inside the assets folder (no /, \\ or : at its "
                   "start), got \"%s\"",
                   shown(text, b), 0, 0);
    for (const char *p = text; *p;) {
        size_t len = strcspn(p, "/");
        if ((len == 2 && p[0] == '.' && p[1] == '.') || len == 0)
            return say(msg, msg_size,
                       "must stay inside the assets folder (no \"..\" or empty parts), got "
                       "\"%s\"",
                       shown(text, b), 0, 0);
        p += len;
        if (*p == '/')
            p++;
        if (*p == 0 && p[-1] == '/')
            return say(msg, msg_size, "must name a file, got \"%s\"", shown(text, b), 0, 0);
    }
    return NULL;
}

void catdb_format_real(double v, char *buf, size_t size)
{
    if (v == 0)
        v = 0;
    snprintf(buf, size, "%.15g", v);
    if (strtod(buf, NULL) != v)
        snprintf(buf, size, "%.17g", v);
}

void catdb_format_money(long long cents, char *buf, size_t size)
{
    snprintf(buf, size, "%lld.%02lld", cents / 100, cents % 100);
}
