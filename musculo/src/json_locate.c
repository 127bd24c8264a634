/* SPDX-License-Identifier: MIT */
/* A scanner over a document jansson already accepted: it only has to
 * skip values and compare keys, never to reject anything. Every read
 * stops at the end of the buffer all the same, and every loop moves the
 * cursor on, so a text the scanner misjudges can at worst give no
 * position or a wrong one, never a scan that does not end. jansson
 * accepts more than JSON: it passes over a NUL byte anywhere outside a
 * string ("[0,-9.8\0]" is an array of two numbers). */
#include <stdint.h>

#include "json_locate.h"

typedef struct cursor {
    const char *at, *end;
    int line;
    int column; /* characters already read on this line */
} cursor;

static char peek(const cursor *c) { return c->at < c->end ? *c->at : '\0'; }

static void advance(cursor *c)
{
    if (c->at >= c->end) {
        return;
    }
    if (*c->at == '\n') {
        ++c->line;
        c->column = 0;
    } else if (((unsigned char)*c->at & 0xC0) != 0x80) {
        /* jansson counts a UTF-8 sequence as one column: count lead bytes only */
        ++c->column;
    }
    ++c->at;
}

static mu_json_position here(const cursor *c) { return (mu_json_position){c->line, c->column + 1}; }

static void skip_space(cursor *c)
{
    for (char ch = peek(c); ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r'; ch = peek(c)) {
        advance(c);
    }
}

static uint32_t read_hex4(cursor *c)
{
    uint32_t value = 0;
    for (int i = 0; i < 4; ++i) {
        char ch = peek(c);
        uint32_t digit = ch >= '0' && ch <= '9'   ? (uint32_t)(ch - '0')
                         : ch >= 'a' && ch <= 'f' ? (uint32_t)(ch - 'a' + 10)
                         : ch >= 'A' && ch <= 'F' ? (uint32_t)(ch - 'A' + 10)
                                                  : 0;
        value = value * 16 + digit;
        advance(c);
    }
    return value;
}

static int encode_utf8(uint32_t code, unsigned char bytes[4])
{
    if (code < 0x80) {
        bytes[0] = (unsigned char)code;
        return 1;
    }
    if (code < 0x800) {
        bytes[0] = (unsigned char)(0xC0 | (code >> 6));
        bytes[1] = (unsigned char)(0x80 | (code & 0x3F));
        return 2;
    }
    if (code < 0x10000) {
        bytes[0] = (unsigned char)(0xE0 | (code >> 12));
        bytes[1] = (unsigned char)(0x80 | ((code >> 6) & 0x3F));
        bytes[2] = (unsigned char)(0x80 | (code & 0x3F));
        return 3;
    }
    bytes[0] = (unsigned char)(0xF0 | (code >> 18));
    bytes[1] = (unsigned char)(0x80 | ((code >> 12) & 0x3F));
    bytes[2] = (unsigned char)(0x80 | ((code >> 6) & 0x3F));
    bytes[3] = (unsigned char)(0x80 | (code & 0x3F));
    return 4;
}

/* Decodes one escape sequence after its backslash into UTF-8 bytes. */
static int read_escape(cursor *c, unsigned char bytes[4])
{
    char ch = peek(c);
    advance(c);
    switch (ch) {
    case 'b':
        bytes[0] = '\b';
        return 1;
    case 'f':
        bytes[0] = '\f';
        return 1;
    case 'n':
        bytes[0] = '\n';
        return 1;
    case 'r':
        bytes[0] = '\r';
        return 1;
    case 't':
        bytes[0] = '\t';
        return 1;
    case 'u': {
        uint32_t code = read_hex4(c);
        if (code >= 0xD800 && code < 0xDC00 && peek(c) == '\\') {
            /* jansson accepted the text, so a high surrogate is followed by \u and its low half */
            advance(c);
            advance(c);
            code = 0x10000 + ((code - 0xD800) << 10) + (read_hex4(c) - 0xDC00);
        }
        return encode_utf8(code, bytes);
    }
    default: /* '"', '\\', '/' stand for themselves */
        bytes[0] = (unsigned char)ch;
        return 1;
    }
}

/* Reads a string token; returns whether its decoded text is `match`. */
static bool read_string(cursor *c, const char *match)
{
    size_t matched = 0;
    bool equal = true;
    advance(c); /* the opening quote */
    while (c->at < c->end && peek(c) != '"') {
        unsigned char bytes[4];
        int count = 1;
        if (peek(c) == '\\') {
            advance(c);
            count = read_escape(c, bytes);
        } else {
            bytes[0] = (unsigned char)peek(c);
            advance(c);
        }
        for (int i = 0; i < count && equal; ++i) {
            equal = (unsigned char)match[matched] == bytes[i];
            ++matched;
        }
    }
    advance(c); /* the closing quote */
    return equal && match[matched] == '\0';
}

static void skip_value(cursor *c);

/* Skips the members of an object or the elements of an array, the
 * cursor on the opening bracket. */
static void skip_container(cursor *c, char close)
{
    advance(c);
    skip_space(c);
    while (c->at < c->end && peek(c) != close) {
        const char *start = c->at;
        if (close == '}') {
            read_string(c, "");
            skip_space(c);
            advance(c); /* ':' */
            skip_space(c);
        }
        skip_value(c);
        skip_space(c);
        if (peek(c) == ',') {
            advance(c);
            skip_space(c);
        }
        if (c->at == start) {
            /* A byte no value starts with, such as a NUL jansson passed
             * over: step past it as jansson did. */
            advance(c);
        }
    }
    advance(c);
}

static void skip_value(cursor *c)
{
    switch (peek(c)) {
    case '{':
        skip_container(c, '}');
        return;
    case '[':
        skip_container(c, ']');
        return;
    case '"':
        read_string(c, "");
        return;
    default: /* a number, true, false or null: up to the next delimiter */
        for (char ch = peek(c);
             ch != '\0' && ch != ',' && ch != '}' && ch != ']' && ch != ' ' && ch != '\t' && ch != '\n' && ch != '\r';
             ch = peek(c)) {
            advance(c);
        }
        return;
    }
}

/* Moves the cursor from an object's '{' to the value of member `key`
 * (true), leaving *key_position at the key's opening quote. */
static bool enter_member(cursor *c, const char *key, mu_json_position *key_position)
{
    if (peek(c) != '{') {
        return false;
    }
    advance(c);
    skip_space(c);
    while (peek(c) == '"') {
        *key_position = here(c);
        bool found = read_string(c, key);
        skip_space(c);
        advance(c); /* ':' */
        skip_space(c);
        if (found) {
            return true;
        }
        skip_value(c);
        skip_space(c);
        if (peek(c) == ',') {
            advance(c);
            skip_space(c);
        }
    }
    return false;
}

/* Moves the cursor from an array's '[' to its element `index`. */
static bool enter_element(cursor *c, size_t index)
{
    if (peek(c) != '[') {
        return false;
    }
    advance(c);
    skip_space(c);
    for (size_t i = 0; i < index; ++i) {
        if (c->at >= c->end || peek(c) == ']') {
            return false;
        }
        skip_value(c);
        skip_space(c);
        if (peek(c) == ',') {
            advance(c);
            skip_space(c);
        }
    }
    return c->at < c->end && peek(c) != ']';
}

bool mu_json_locate(const char *text, size_t length, const mu_json_step *steps, int step_count, bool at_key,
                    mu_json_position *out)
{
    cursor c = {.at = text, .end = text + length, .line = 1, .column = 0};
    mu_json_position key_position = {0, 0};
    skip_space(&c);
    for (int i = 0; i < step_count; ++i) {
        bool entered =
            steps[i].key != NULL ? enter_member(&c, steps[i].key, &key_position) : enter_element(&c, steps[i].index);
        if (!entered) {
            return false;
        }
    }
    if (at_key) {
        if (step_count == 0 || steps[step_count - 1].key == NULL) {
            return false;
        }
        *out = key_position;
    } else {
        *out = here(&c);
    }
    return true;
}
