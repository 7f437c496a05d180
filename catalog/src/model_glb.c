/* The GLB container: 12-byte header, a JSON chunk, an optional BIN chunk.
 * (glTF 2.0 specification, section 4.4 "Binary glTF Layout".)
 *
 * tinygltf parses the container again; this check accepts only what it accepts, so that a bad
 * container is reported here with a precise message and tinygltf never sees one. */
#include "model_internal.h"

#include <stdint.h>

#define GLB_CHUNK_JSON 0x4E4F534Au
#define GLB_CHUNK_BIN 0x004E4942u

static uint32_t u32le(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

cat_result cat_glb_check(const cat_msg *msg, const unsigned char *bytes, size_t size,
                         const unsigned char **json, size_t *json_size)
{
    *json = NULL;
    *json_size = 0;
    if (size < 20)
        return cat_fail(msg, CAT_ERR_PARSE,
                        "truncated GLB: %zu bytes, header and JSON chunk header need 20", size);
    uint32_t version = u32le(bytes + 4);
    uint32_t length = u32le(bytes + 8);
    if (version != 2)
        return cat_fail(msg, CAT_ERR_UNSUPPORTED, "GLB version %u; only version 2 is supported",
                        version);
    if (length > size)
        return cat_fail(msg, CAT_ERR_PARSE,
                        "truncated GLB: the header says %u bytes, the file has %zu", length, size);
    if (length < 20)
        return cat_fail(msg, CAT_ERR_PARSE, "GLB header gives a length of %u bytes, less than 20",
                        length);
    uint64_t json_len = u32le(bytes + 12);
    if (u32le(bytes + 16) != GLB_CHUNK_JSON)
        return cat_fail(msg, CAT_ERR_PARSE, "the first GLB chunk is not JSON");
    if (json_len < 1 || 20 + json_len > length)
        return cat_fail(msg, CAT_ERR_PARSE,
                        "GLB JSON chunk of %llu bytes does not fit the GLB's %u bytes",
                        (unsigned long long)json_len, length);
    uint64_t end = 20 + json_len;
    if (end < length) {
        if (end + 12 > length)
            return cat_fail(msg, CAT_ERR_PARSE,
                            "GLB has %llu stray bytes after its JSON chunk, too few for a chunk",
                            (unsigned long long)(length - end));
        uint64_t bin_len = u32le(bytes + end);
        uint32_t bin_type = u32le(bytes + end + 4);
        if (bin_type != GLB_CHUNK_BIN)
            return cat_fail(msg, CAT_ERR_PARSE, "the second GLB chunk is not BIN");
        if (bin_len < 4 || bin_len % 4 != 0)
            return cat_fail(msg, CAT_ERR_PARSE,
                            "GLB BIN chunk length %llu is not a positive multiple of 4",
                            (unsigned long long)bin_len);
        if (end + 8 + bin_len > length)
            return cat_fail(msg, CAT_ERR_PARSE,
                            "truncated GLB: the BIN chunk of %llu bytes runs past the GLB's end",
                            (unsigned long long)bin_len);
    }
    *json = bytes + 20;
    *json_size = (size_t)json_len;
    return CAT_OK;
}
