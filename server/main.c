/* main.c — mechmat-server: flags, start-up, course reloads, graceful stop.
 *
 *   mechmat-server [--host 127.0.0.1] [--port 8080] [--threads N] [--io-threads 2]
 *                  [--course FILE] [--cache-mb 64] [--queue 1024]
 *                  [--max-connections 10000] [--light-us 300] [--root DIR] [--web-root DIR]
 *                  [--quiet] [--print-asset-version]
 *
 * The tree it serves from (theory texts, web/, node_modules/ with the
 * browser packages) is --root, else found from where the binary lives,
 * whatever the working directory: the nearest folder above the binary
 * that holds both web/ and exercises/ (the source tree), or
 * <prefix>/share/mechmat for a binary installed in <prefix>/bin.
 *
 * Signals: SIGHUP reads the course file again (and the theory texts); a
 * file that fails keeps the course that runs, with the reason logged.
 * SIGINT and SIGTERM stop: no new connections, running solves finish.
 */
#include <errno.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "mm_api.h"
#include "mm_course.h"
#include "mm_fourier.h"
#include "mm_http.h"

static int is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

static int is_root(const char *dir)
{
    char a[PATH_MAX + 16], b[PATH_MAX + 16];
    snprintf(a, sizeof a, "%s/web", dir);
    snprintf(b, sizeof b, "%s/exercises", dir);
    return is_dir(a) && is_dir(b);
}

/* The tree to serve: above the binary (source tree or installed share),
 * else the working directory. */
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
            char share[PATH_MAX + 32];
            snprintf(share, sizeof share, "%s/share/mechmat", exe);
            if (is_root(exe)) {
                snprintf(root, size, "%s", exe);
                return;
            }
            if (is_root(share) && strlen(share) < size) {
                memcpy(root, share, strlen(share) + 1);
                return;
            }
        }
    }
    if (!getcwd(root, size))
        snprintf(root, size, ".");
}

static void usage(FILE *f)
{
    fprintf(f, "usage: mechmat-server [--host ADDR] [--port N] [--threads N] [--io-threads N] [--course FILE]\n"
               "                      [--cache-mb N] [--queue N] [--max-connections N] [--light-us N]\n"
               "                      [--root DIR] [--web-root DIR] [--quiet] [--print-asset-version]\n");
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

/* The api of the course file (or the built-in course); NULL with err. */
static mm_api *load(const char *root, const char *course_file, mm_error *err)
{
    mm_course *c = course_file ? mm_course_load(course_file, err) : mm_course_builtin();
    if (!c) {
        if (!course_file)
            mm_error_set(err, MM_ENOMEM, "", "out of memory");
        return NULL;
    }
    return mm_api_alloc_course(root, c, err);
}

/* Room for thousands of idle connections: the soft limit of open files
 * raised to the hard one. */
static void raise_file_limit(int want)
{
    struct rlimit rl;
    if (getrlimit(RLIMIT_NOFILE, &rl) != 0)
        return;
    rlim_t need = (rlim_t)want + 256;
    if (rl.rlim_cur < need) {
        rl.rlim_cur = rl.rlim_max < need ? rl.rlim_max : need;
        setrlimit(RLIMIT_NOFILE, &rl);
    }
}

int main(int argc, char **argv)
{
    char root[PATH_MAX], web[PATH_MAX + 8], vendor[PATH_MAX + 16];
    const char *course_file = NULL, *root_flag = NULL, *web_flag = NULL;
    int cache_mb = -1, print_version = 0;
    mm_server_opts o = {.host = "127.0.0.1", .port = 8080, .max_connections = 10000};
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
        } else if (strcmp(a, "--io-threads") == 0) {
            if (!parse_int(a, v, 1, 8, &o.io_threads))
                return 2;
            i++;
        } else if (strcmp(a, "--queue") == 0) {
            if (!parse_int(a, v, 1, 1000000, &o.queue))
                return 2;
            i++;
        } else if (strcmp(a, "--light-us") == 0) {   /* mm_light.h; 0: every solve to the workers */
            if (!parse_int(a, v, 0, 1000000, &o.light_us))
                return 2;
            o.light_us = o.light_us ? o.light_us : -1;
            i++;
        } else if (strcmp(a, "--cache-mb") == 0) {
            if (!parse_int(a, v, 0, 1 << 20, &cache_mb))
                return 2;
            i++;
        } else if (strcmp(a, "--course") == 0 && v)
            course_file = v, i++;
        else if (strcmp(a, "--root") == 0 && v)
            root_flag = v, i++;
        else if (strcmp(a, "--web-root") == 0 && v)
            web_flag = v, i++;
        else if (strcmp(a, "--quiet") == 0)
            o.quiet = 1;
        else if (strcmp(a, "--print-asset-version") == 0)
            print_version = 1;
        else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(stdout);
            return 0;
        } else {
            usage(stderr);
            return 2;
        }
    }
    if (root_flag)
        snprintf(root, sizeof root, "%s", root_flag);
    else
        find_root(root, sizeof root);
    snprintf(web, sizeof web, "%s/web", root);
    snprintf(vendor, sizeof vendor, "%s/node_modules", root);
    o.web_root = web_flag ? web_flag : web;
    o.vendor_root = vendor;
    o.cache_mb = cache_mb;
    if (print_version) {
        char v[32];
        mm_asset_version(o.web_root, o.vendor_root, v);
        printf("%s\n", v);
        return 0;
    }

    /* Block the signals in every thread; main waits for them below. */
    sigset_t sigs;
    sigemptyset(&sigs);
    sigaddset(&sigs, SIGINT);
    sigaddset(&sigs, SIGTERM);
    sigaddset(&sigs, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &sigs, NULL);
    signal(SIGPIPE, SIG_IGN);
    raise_file_limit(o.max_connections);

    mm_error err;
    mm_error_clear(&err);
    mm_api *api = load(root, course_file, &err);
    if (!api) {
        fprintf(stderr, "mechmat: cannot start: %s\n", err.msg);
        return 1;
    }
    const mm_course *c = mm_api_course(api);
    char title[300];
    snprintf(title, sizeof title, "%s", mm_course_title(c));
    int n_ex = mm_course_exercise_count(c);
    mm_server *s = mm_server_start(&o, api, &err);
    if (!s) {
        fprintf(stderr, "mechmat: cannot start: %s\n", err.msg);
        return 1;
    }
    printf("mechmat: listening on http://%s:%d/ (%d exercises, course \"%s\", web root %s)\n", o.host,
           mm_server_port(s), n_ex, title, o.web_root);
    fflush(stdout);

    for (;;) {
        int sig = 0;
        if (sigwait(&sigs, &sig) != 0)
            continue;
        if (sig != SIGHUP) {
            fprintf(stderr, "mechmat: %s received, stopping\n", sig == SIGINT ? "SIGINT" : "SIGTERM");
            break;
        }
        mm_error_clear(&err);
        mm_api *next = load(root, course_file, &err);
        if (!next) {
            fprintf(stderr, "mechmat: SIGHUP: the course was not reloaded, the one running stays: %s\n", err.msg);
            mm_server_note_reload(s, 0);
            continue;
        }
        fprintf(stderr, "mechmat: SIGHUP: course \"%s\" reloaded (%d exercises)\n",
                mm_course_title(mm_api_course(next)), mm_course_exercise_count(mm_api_course(next)));
        mm_server_replace(s, next);
        mm_server_note_reload(s, 1);
    }
    mm_server_stop(s);
    mm_fourier_cleanup();
    return 0;
}
