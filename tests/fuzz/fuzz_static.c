/* fuzz_static.c — URL text through our percent-decoding and the static file
 * resolver, against a web root that holds a file and a symlink out of it.
 * Invariant: whatever resolves lies inside the root. */
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "mm_http.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv);

static char root[PATH_MAX];

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    char dir[] = "/tmp/mm-fuzz-static-XXXXXX", path[PATH_MAX];
    if (!mkdtemp(dir))
        abort();
    snprintf(path, sizeof path, "%s/www", dir);
    mkdir(path, 0755);
    snprintf(path, sizeof path, "%s/www/index.html", dir);
    FILE *f = fopen(path, "w");
    fputs("x", f);
    fclose(f);
    snprintf(path, sizeof path, "%s/secret", dir);
    f = fopen(path, "w");
    fputs("s", f);
    fclose(f);
    char target[PATH_MAX];
    snprintf(target, sizeof target, "%s/secret", dir);
    snprintf(path, sizeof path, "%s/www/leak", dir);
    if (symlink(target, path) != 0)
        abort();
    snprintf(path, sizeof path, "%s/www", dir);
    if (!realpath(path, root))
        abort();
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!root[0])
        LLVMFuzzerInitialize(NULL, NULL);
    if (size > 2048)
        return 0;
    char url[2050], out[PATH_MAX];
    memcpy(url, data, size);
    url[size] = '\0';
    mm_http_unescape(url);
    if (mm_static_resolve(root, url, out, sizeof out) == MM_OK) {
        size_t n = strlen(root);
        if (strncmp(out, root, n) != 0 || out[n] != '/' || strstr(out, "secret"))
            abort();
    }
    return 0;
}
