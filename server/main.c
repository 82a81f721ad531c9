/* main.c — mechmat-server: flags, start-up, graceful shutdown.
 *
 *   mechmat-server [--host 127.0.0.1] [--port 8080] [--threads N]
 *                  [--web-root DIR] [--quiet]
 *
 * The source tree (theory texts, web/, node_modules/) is found from where
 * the binary lives, whatever the working directory: the nearest folder
 * above the binary that holds both web/ and exercises/.
 */
#include <errno.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "mm_api.h"
#include "mm_fourier.h"
#include "mm_http.h"

static int is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

static int is_source_root(const char *dir)
{
    char a[PATH_MAX + 16], b[PATH_MAX + 16];
    snprintf(a, sizeof a, "%s/web", dir);
    snprintf(b, sizeof b, "%s/exercises", dir);
    return is_dir(a) && is_dir(b);
}

/* The source root: above the binary, else the working directory. */
static void find_root(char *root, size_t size)
{
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
        exe[n] = '\0';
        for (int up = 0; up < 5; up++) {
            char *slash = strrchr(exe, '/');
            if (!slash || slash == exe)
                break;
            *slash = '\0';
            if (is_source_root(exe)) {
                snprintf(root, size, "%s", exe);
                return;
            }
        }
    }
    if (!getcwd(root, size))
        snprintf(root, size, ".");
}

static void usage(FILE *f)
{
    fprintf(f, "usage: mechmat-server [--host ADDR] [--port N] [--threads N] "
               "[--web-root DIR] [--max-connections N] [--quiet]\n");
}

static int parse_int(const char *flag, const char *v, int lo, int hi, int *out)
{
    char *end;
    errno = 0;
    long x = v ? strtol(v, &end, 10) : 0;
    if (!v || errno || *end || x < lo || x > hi) {
        fprintf(stderr, "mechmat: %s must be a whole number from %d to %d\n", flag, lo, hi);
        return 0;
    }
    *out = (int)x;
    return 1;
}

int main(int argc, char **argv)
{
    char root[PATH_MAX], web[PATH_MAX + 8], vendor[PATH_MAX + 16];
    find_root(root, sizeof root);
    snprintf(web, sizeof web, "%s/web", root);
    snprintf(vendor, sizeof vendor, "%s/node_modules", root);

    mm_server_opts o = {.host = "127.0.0.1", .port = 8080, .web_root = web,
                        .vendor_root = vendor, .max_connections = 512};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--host") == 0 && v)
            o.host = v, i++;
        else if (strcmp(a, "--port") == 0) {
            if (!parse_int(a, v, 0, 65535, &o.port))
                return 2;
            i++;
        } else if (strcmp(a, "--threads") == 0) {
            if (!parse_int(a, v, 1, 256, &o.threads))
                return 2;
            i++;
        } else if (strcmp(a, "--max-connections") == 0) {
            if (!parse_int(a, v, 1, 100000, &o.max_connections))
                return 2;
            i++;
        } else if (strcmp(a, "--web-root") == 0 && v)
            o.web_root = v, i++;
        else if (strcmp(a, "--quiet") == 0)
            o.quiet = 1;
        else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(stdout);
            return 0;
        } else {
            usage(stderr);
            return 2;
        }
    }

    /* Block the stop signals in every thread; main waits for them below. */
    sigset_t stop;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stop, NULL);
    signal(SIGPIPE, SIG_IGN);

    mm_error err;
    mm_error_clear(&err);
    mm_api *api = mm_api_alloc(root, &err);
    if (!api) {
        fprintf(stderr, "mechmat: cannot start: %s\n", err.msg);
        return 1;
    }
    mm_server *s = mm_server_start(&o, api, &err);
    if (!s) {
        fprintf(stderr, "mechmat: cannot start: %s\n", err.msg);
        mm_api_free(api);
        return 1;
    }
    printf("mechmat: listening on http://%s:%d/ (%d exercises, web root %s)\n", o.host,
           mm_server_port(s), mm_exercise_count, o.web_root);
    fflush(stdout);

    int sig = 0;
    sigwait(&stop, &sig);
    fprintf(stderr, "mechmat: %s received, stopping\n", sig == SIGINT ? "SIGINT" : "SIGTERM");
    mm_server_stop(s);
    mm_api_free(api);
    mm_fourier_cleanup();
    return 0;
}
