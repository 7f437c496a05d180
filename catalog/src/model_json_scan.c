/* A strict JSON well-formedness check (RFC 8259) run before tinygltf sees the text.
 *
 * It gives a precise "line L, column C" for malformed files and enforces the limits that keep
 * the JSON library's and tinygltf's memory and stack use bounded: nesting depth, number of
 * values and of objects (tinygltf turns each object into a struct of up to 2 KiB), the length of a
 * single string (which bounds every data: URI), and the sum of the buffers' byteLength (tinygltf
 * allocates that much, e.g. copying a GLB's BIN chunk once per buffer). It builds nothing; one
 * pass, no recursion. UTF-8 is checked as nlohmann::json checks it, so the two agree on what is
 * valid. */
#include "model_internal.h"

#include <stdint.h>

/* Longest JSON string accepted: the base64 text of a CAT_MODEL_MAX_DATA_URI_BYTES data: URI,
 * plus room for its "data:<mime type>;base64," header. */
#define MAX_STRING_BYTES ((size_t)CAT_MODEL_MAX_DATA_URI_BYTES / 3 * 4 + 8 + 256)

enum expect { VALUE, VALUE_OR_CLOSE, KEY, KEY_OR_CLOSE, COLON, COMMA_OR_CLOSE, DONE };

/* The object keys the scan follows, to find buffers[i].byteLength. */
enum key { KEY_OTHER, KEY_BUFFERS, KEY_BYTE_LENGTH };

typedef struct scan {
    const unsigned char *s;
    size_t n, i;
    const char *problem;
} scan;

static cat_result parse_error(const cat_msg *msg, const scan *sc)
{
    size_t line = 1, col = 1;
    for (size_t k = 0; k < sc->i && k < sc->n; k++) {
        if (sc->s[k] == '\n') {
            line++;
            col = 1;
        } else {
            col++;
        }
    }
    return cat_fail(msg, CAT_ERR_PARSE,
                    "not a glTF file (JSON parse error at line %zu, column %zu: %s)", line, col,
                    sc->problem);
}

static int hex4(const unsigned char *p, unsigned *v)
{
    *v = 0;
    for (int k = 0; k < 4; k++) {
        unsigned c = p[k], d;
        if (c >= '0' && c <= '9')
            d = c - '0';
        else if (c >= 'a' && c <= 'f')
            d = c - 'a' + 10;
        else if (c >= 'A' && c <= 'F')
            d = c - 'A' + 10;
        else
            return 0;
        *v = *v * 16 + d;
    }
    return 1;
}

/* Length of a valid UTF-8 sequence starting at s[i] (which is >= 0x80), 0 if invalid. */
static size_t utf8_length(const unsigned char *s, size_t n, size_t i)
{
    unsigned c = s[i];
    size_t len;
    unsigned lo = 0x80, hi = 0xBF; /* allowed range of the second byte */
    if (c >= 0xC2 && c <= 0xDF)
        len = 2;
    else if (c >= 0xE0 && c <= 0xEF) {
        len = 3;
        if (c == 0xE0)
            lo = 0xA0; /* no overlong forms */
        if (c == 0xED)
            hi = 0x9F; /* no surrogates */
    } else if (c >= 0xF0 && c <= 0xF4) {
        len = 4;
        if (c == 0xF0)
            lo = 0x90;
        if (c == 0xF4)
            hi = 0x8F; /* nothing above U+10FFFF */
    } else
        return 0;
    if (n - i < len)
        return 0;
    if (s[i + 1] < lo || s[i + 1] > hi)
        return 0;
    for (size_t k = 2; k < len; k++)
        if (s[i + k] < 0x80 || s[i + k] > 0xBF)
            return 0;
    return len;
}

/* Scans the string starting at the opening quote sc->i; leaves sc->i after the closing one. */
static int scan_string(scan *sc, size_t *raw_length)
{
    size_t start = ++sc->i;
    while (sc->i < sc->n) {
        unsigned c = sc->s[sc->i];
        if (c == '"') {
            *raw_length = sc->i - start;
            sc->i++;
            return 1;
        }
        if (c < 0x20) {
            sc->problem = "control character in a string";
            return 0;
        }
        if (c == '\\') {
            if (sc->i + 1 >= sc->n)
                break;
            unsigned e = sc->s[sc->i + 1];
            if (e == 'u') {
                unsigned v, v2;
                if (sc->n - sc->i < 6 || !hex4(sc->s + sc->i + 2, &v)) {
                    sc->problem = "bad \\u escape in a string";
                    return 0;
                }
                sc->i += 6;
                if (v >= 0xDC00 && v <= 0xDFFF) {
                    sc->problem = "lone low surrogate escape in a string";
                    return 0;
                }
                if (v >= 0xD800 && v <= 0xDBFF) {
                    if (sc->n - sc->i < 6 || sc->s[sc->i] != '\\' || sc->s[sc->i + 1] != 'u' ||
                        !hex4(sc->s + sc->i + 2, &v2) || v2 < 0xDC00 || v2 > 0xDFFF) {
                        sc->problem = "high surrogate escape without its low surrogate";
                        return 0;
                    }
                    sc->i += 6;
                }
                continue;
            }
            if (e != '"' && e != '\\' && e != '/' && e != 'b' && e != 'f' && e != 'n' && e != 'r' &&
                e != 't') {
                sc->problem = "bad escape in a string";
                return 0;
            }
            sc->i += 2;
            continue;
        }
        if (c >= 0x80) {
            size_t len = utf8_length(sc->s, sc->n, sc->i);
            if (len == 0) {
                sc->problem = "invalid UTF-8 in a string";
                return 0;
            }
            sc->i += len;
            continue;
        }
        sc->i++;
    }
    sc->problem = "unterminated string";
    return 0;
}

/* Does the raw (still escaped) JSON string s[0..n) equal the ASCII word? nlohmann decodes
 * escapes in keys, so "byte\u004cength" must count as "byteLength" here too. */
static int key_equals(const unsigned char *s, size_t n, const char *word)
{
    size_t i = 0, k = 0;
    while (i < n) {
        unsigned c = s[i];
        if (c == '\\' && i + 1 < n) {
            unsigned e = s[i + 1];
            if (e == 'u') {
                if (n - i < 6 || !hex4(s + i + 2, &c))
                    return 0;
                i += 6;
            } else {
                c = e == 'b'   ? '\b'
                    : e == 'f' ? '\f'
                    : e == 'n' ? '\n'
                    : e == 'r' ? '\r'
                    : e == 't' ? '\t'
                               : e;
                i += 2;
            }
        } else {
            i++;
        }
        if (!word[k] || c != (unsigned char)word[k])
            return 0;
        k++;
    }
    return word[k] == '\0';
}

static int is_digit(unsigned c)
{
    return c >= '0' && c <= '9';
}

static int scan_number(scan *sc)
{
    const unsigned char *s = sc->s;
    size_t n = sc->n;
    if (s[sc->i] == '-')
        sc->i++;
    if (sc->i >= n || !is_digit(s[sc->i])) {
        sc->problem = "bad number";
        return 0;
    }
    if (s[sc->i] == '0')
        sc->i++;
    else
        while (sc->i < n && is_digit(s[sc->i]))
            sc->i++;
    if (sc->i < n && s[sc->i] == '.') {
        sc->i++;
        if (sc->i >= n || !is_digit(s[sc->i])) {
            sc->problem = "bad number: no digit after '.'";
            return 0;
        }
        while (sc->i < n && is_digit(s[sc->i]))
            sc->i++;
    }
    if (sc->i < n && (s[sc->i] == 'e' || s[sc->i] == 'E')) {
        sc->i++;
        if (sc->i < n && (s[sc->i] == '+' || s[sc->i] == '-'))
            sc->i++;
        if (sc->i >= n || !is_digit(s[sc->i])) {
            sc->problem = "bad number: no digit in the exponent";
            return 0;
        }
        while (sc->i < n && is_digit(s[sc->i]))
            sc->i++;
    }
    return 1;
}

static int scan_literal(scan *sc, const char *word)
{
    size_t k = 0;
    for (; word[k]; k++)
        if (sc->i + k >= sc->n || sc->s[sc->i + k] != (unsigned char)word[k]) {
            sc->problem = "invalid literal";
            return 0;
        }
    sc->i += k;
    return 1;
}

cat_result cat_json_scan(const cat_msg *msg, const unsigned char *text, size_t size)
{
    if (size > CAT_MODEL_MAX_JSON_BYTES)
        return cat_fail(msg, CAT_ERR_TOO_LARGE, "JSON text of %zu bytes, the limit is %u", size,
                        CAT_MODEL_MAX_JSON_BYTES);
    scan sc = {text, size, 0, NULL};
    if (size >= 3 && text[0] == 0xEF && text[1] == 0xBB && text[2] == 0xBF)
        sc.i = 3;                                       /* UTF-8 byte order mark */
    char stack[CAT_MODEL_MAX_JSON_DEPTH];               /* '[' or '{' */
    unsigned char keys[CAT_MODEL_MAX_JSON_DEPTH] = {0}; /* enum key of each object's last key */
    double buffer_bytes = 0.0;                          /* sum of buffers[i].byteLength */
    int depth = 0;
    size_t values = 0, objects = 0;
    enum expect state = VALUE;
    for (;;) {
        while (sc.i < size && (text[sc.i] == ' ' || text[sc.i] == '\t' || text[sc.i] == '\n' ||
                               text[sc.i] == '\r'))
            sc.i++;
        if (sc.i >= size) {
            if (state == DONE)
                return CAT_OK;
            sc.problem = size == 0 ? "empty text" : "unexpected end of text";
            return parse_error(msg, &sc);
        }
        unsigned c = text[sc.i];
        int value_done = 0;
        switch (state) {
        case DONE:
            sc.problem = "unexpected text after the top-level value";
            return parse_error(msg, &sc);
        case COLON:
            if (c != ':') {
                sc.problem = "expected ':' after an object key";
                return parse_error(msg, &sc);
            }
            sc.i++;
            state = VALUE;
            continue;
        case COMMA_OR_CLOSE: {
            char top = stack[depth - 1];
            if (c == ',') {
                sc.i++;
                state = top == '[' ? VALUE : KEY;
                continue;
            }
            if ((top == '[' && c == ']') || (top == '{' && c == '}')) {
                sc.i++;
                depth--;
                value_done = 1;
                break;
            }
            sc.problem = top == '[' ? "expected ',' or ']'" : "expected ',' or '}'";
            return parse_error(msg, &sc);
        }
        case KEY:
        case KEY_OR_CLOSE: {
            if (c == '}' && state == KEY_OR_CLOSE) {
                sc.i++;
                depth--;
                value_done = 1;
                break;
            }
            if (c != '"') {
                sc.problem = "expected a string as object key";
                return parse_error(msg, &sc);
            }
            size_t at = sc.i + 1, len;
            if (!scan_string(&sc, &len))
                return parse_error(msg, &sc);
            keys[depth - 1] = key_equals(text + at, len, "buffers")      ? KEY_BUFFERS
                              : key_equals(text + at, len, "byteLength") ? KEY_BYTE_LENGTH
                                                                         : KEY_OTHER;
            state = COLON;
            continue;
        }
        case VALUE:
        case VALUE_OR_CLOSE:
            if (c == ']' && state == VALUE_OR_CLOSE) {
                sc.i++;
                depth--;
                value_done = 1;
                break;
            }
            if (++values > CAT_MODEL_MAX_JSON_VALUES)
                return cat_fail(msg, CAT_ERR_TOO_LARGE, "JSON text has more than %u values",
                                CAT_MODEL_MAX_JSON_VALUES);
            if (c == '{' && ++objects > CAT_MODEL_MAX_JSON_OBJECTS)
                return cat_fail(msg, CAT_ERR_TOO_LARGE, "JSON text has more than %u objects",
                                CAT_MODEL_MAX_JSON_OBJECTS);
            if (c == '[' || c == '{') {
                if (depth == CAT_MODEL_MAX_JSON_DEPTH)
                    return cat_fail(msg, CAT_ERR_TOO_LARGE,
                                    "JSON nesting deeper than %d levels at byte %zu",
                                    CAT_MODEL_MAX_JSON_DEPTH, sc.i);
                stack[depth++] = (char)c;
                sc.i++;
                state = c == '[' ? VALUE_OR_CLOSE : KEY_OR_CLOSE;
                continue;
            }
            if (c == '"') {
                size_t at = sc.i, len = 0;
                if (!scan_string(&sc, &len))
                    return parse_error(msg, &sc);
                if (len > MAX_STRING_BYTES)
                    return cat_fail(msg, CAT_ERR_TOO_LARGE,
                                    "a JSON string at byte %zu is %zu bytes long; data URIs "
                                    "over %u MiB are refused",
                                    at, len, CAT_MODEL_MAX_DATA_URI_BYTES / (1024u * 1024u));
            } else if (c == '-' || is_digit(c)) {
                size_t at = sc.i;
                if (!scan_number(&sc))
                    return parse_error(msg, &sc);
                if (depth == 3 && stack[0] == '{' && keys[0] == KEY_BUFFERS && stack[1] == '[' &&
                    stack[2] == '{' && keys[2] == KEY_BYTE_LENGTH) {
                    /* tinygltf takes only an unsigned integer token here; others it refuses */
                    double v = 0.0;
                    for (size_t k = at; k < sc.i && is_digit(text[k]); k++)
                        v = v * 10.0 + (text[k] - '0');
                    buffer_bytes += v;
                    if (buffer_bytes > (double)CAT_MODEL_MAX_BUFFER_BYTES)
                        return cat_fail(msg, CAT_ERR_TOO_LARGE,
                                        "the buffers' byteLength add up to more than %u bytes",
                                        CAT_MODEL_MAX_BUFFER_BYTES);
                }
            } else if (c == 't' || c == 'f' || c == 'n') {
                if (!scan_literal(&sc, c == 't' ? "true" : c == 'f' ? "false" : "null"))
                    return parse_error(msg, &sc);
            } else {
                sc.problem = "expected a value";
                return parse_error(msg, &sc);
            }
            value_done = 1;
            break;
        }
        if (value_done)
            state = depth == 0 ? DONE : COMMA_OR_CLOSE;
    }
}
