/* rtapi_string.c: strlcpy/strlcat and argv splitting for realtime code. */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include "rtapi_string.h"

/* Copy with truncation; dst is always terminated when size > 0. */
size_t rtapi_strlcpy(char *dst, const char *src, size_t size)
{
    size_t len = strlen(src);

    if (size > 0) {
        size_t n = len < size - 1 ? len : size - 1;
        memcpy(dst, src, n);
        dst[n] = '\0';
    }
    return len;
}

/* Append with truncation; returns the length it tried to create. */
size_t rtapi_strlcat(char *dst, const char *src, size_t size)
{
    size_t used = strnlen(dst, size);

    if (used == size)
        return size + strlen(src);
    return used + rtapi_strlcpy(dst + used, src, size - used);
}

/* Count blank-separated words in str. */
static int count_words(const char *str)
{
    int n = 0;

    while (*str) {
        while (isspace((unsigned char)*str))
            str++;
        if (!*str)
            break;
        n++;
        while (*str && !isspace((unsigned char)*str))
            str++;
    }
    return n;
}

/* Split str on blanks into one allocation: pointer vector followed by the text. */
char **rtapi_argv_split(int gfp, const char *str, int *argcp)
{
    int n = count_words(str), i = 0;
    size_t len = strlen(str) + 1;
    char **argv = malloc((n + 1) * sizeof(char *) + len);
    char *text;

    (void)gfp;
    if (!argv)
        return NULL;
    text = (char *)(argv + n + 1);
    memcpy(text, str, len);
    while (*text) {
        while (isspace((unsigned char)*text))
            *text++ = '\0';
        if (!*text)
            break;
        argv[i++] = text;
        while (*text && !isspace((unsigned char)*text))
            text++;
    }
    argv[i] = NULL;
    if (argcp)
        *argcp = n;
    return argv;
}

/* Free a vector made by rtapi_argv_split. */
void rtapi_argv_free(char **argv)
{
    free(argv);
}
