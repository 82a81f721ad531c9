/* mm_server_fixture.h — start the real server binary on a free port and
 * talk HTTP to it with libcurl, for the HTTP tests.
 *
 * The binary is $MM_SERVER (default build/mechmat-server).  It is started
 * with --port 0 and the port is read from its first line of output.
 */
#ifndef MM_SERVER_FIXTURE_H
#define MM_SERVER_FIXTURE_H

#include <curl/curl.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

typedef struct mm_fixture {
    pid_t pid;
    int port;
    FILE *out;        /* the server's stdout */
} mm_fixture;

/* Start the server with extra arguments (NULL-terminated list, may be NULL).
 * Returns 0 on success. */
static int mm_fixture_start(mm_fixture *f, const char *const *extra)
{
    const char *bin = getenv("MM_SERVER");
    if (!bin)
        bin = "build/mechmat-server";
    int fds[2];
    if (pipe(fds) != 0)
        return -1;
    const char *argv[32] = {bin, "--port", "0", "--quiet", "--threads", "4"};
    int n = 6;
    for (int i = 0; extra && extra[i] && n < 30; i++)
        argv[n++] = extra[i];
    argv[n] = NULL;
    f->pid = fork();
    if (f->pid < 0)
        return -1;
    if (f->pid == 0) {
        dup2(fds[1], 1);
        close(fds[0]);
        close(fds[1]);
        execv(bin, (char *const *)argv);
        _exit(127);
    }
    close(fds[1]);
    f->out = fdopen(fds[0], "r");
    char line[512];
    if (!fgets(line, sizeof line, f->out))
        return -1;
    const char *p = strstr(line, "127.0.0.1:");
    if (!p)
        return -1;
    f->port = atoi(p + 10);
    return f->port > 0 ? 0 : -1;
}

/* SIGTERM and wait; returns the exit status (0 = a clean stop). */
static int mm_fixture_stop(mm_fixture *f)
{
    int status = -1;
    kill(f->pid, SIGTERM);
    if (waitpid(f->pid, &status, 0) != f->pid)
        return -1;
    if (f->out)
        fclose(f->out);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

typedef struct mm_reply {
    long status;
    char *body;       /* NUL-terminated */
    size_t len;
    char headers[4096];
} mm_reply;

static size_t mm_collect(char *p, size_t size, size_t n, void *ud)
{
    mm_reply *r = ud;
    size_t add = size * n;
    char *b = realloc(r->body, r->len + add + 1);
    if (!b)
        return 0;
    memcpy(b + r->len, p, add);
    r->body = b;
    r->len += add;
    r->body[r->len] = '\0';
    return add;
}

static size_t mm_collect_header(char *p, size_t size, size_t n, void *ud)
{
    mm_reply *r = ud;
    size_t used = strlen(r->headers), add = size * n;
    if (used + add < sizeof r->headers) {
        memcpy(r->headers + used, p, add);
        r->headers[used + add] = '\0';
    }
    return add;
}

/* One request.  path is sent as is (no normalisation of "..").  body NULL
 * for no body; method NULL for GET (or POST when body is given). */
static int mm_http(const mm_fixture *f, const char *method, const char *path,
                   const char *body, size_t body_len, mm_reply *r)
{
    memset(r, 0, sizeof *r);
    r->body = calloc(1, 1);
    CURL *c = curl_easy_init();
    size_t url_size = strlen(path) + 64;
    char *url = malloc(url_size);
    snprintf(url, url_size, "http://127.0.0.1:%d%s", f->port, path);
    curl_easy_setopt(c, CURLOPT_URL, url);
    curl_easy_setopt(c, CURLOPT_PATH_AS_IS, 1L);
    curl_easy_setopt(c, CURLOPT_WRITEFUNCTION, mm_collect);
    curl_easy_setopt(c, CURLOPT_WRITEDATA, r);
    curl_easy_setopt(c, CURLOPT_HEADERFUNCTION, mm_collect_header);
    curl_easy_setopt(c, CURLOPT_HEADERDATA, r);
    curl_easy_setopt(c, CURLOPT_TIMEOUT, 30L);
    struct curl_slist *h = NULL;
    if (body) {
        h = curl_slist_append(h, "Content-Type: application/json");
        h = curl_slist_append(h, "Expect:");
        curl_easy_setopt(c, CURLOPT_HTTPHEADER, h);
        curl_easy_setopt(c, CURLOPT_POSTFIELDS, body);
        curl_easy_setopt(c, CURLOPT_POSTFIELDSIZE_LARGE, (curl_off_t)body_len);
    }
    if (method)
        curl_easy_setopt(c, CURLOPT_CUSTOMREQUEST, method);
    if (method && strcmp(method, "HEAD") == 0)
        curl_easy_setopt(c, CURLOPT_NOBODY, 1L);
    CURLcode rc = curl_easy_perform(c);
    curl_easy_getinfo(c, CURLINFO_RESPONSE_CODE, &r->status);
    curl_slist_free_all(h);
    curl_easy_cleanup(c);
    free(url);
    return rc == CURLE_OK ? 0 : -1;
}

static void mm_reply_free(mm_reply *r)
{
    free(r->body);
    r->body = NULL;
}

#endif
