/* bare_mhd.c — the ceiling: a libmicrohttpd endpoint that answers every
 * request with the same 200-byte JSON, nothing else (PERFORMANCE.md's
 * yardstick).  Its requests/s in the same run is what `make bench` and
 * `make loadtest` divide the server's figures by.
 *
 *   bare_mhd [pool|single] [BYTES]
 *                              pool: 2 epoll threads (the best libmicrohttpd
 *                              does here); single: one epoll thread, as the
 *                              server's event thread; BYTES: answer that
 *                              many bytes instead (the 200-byte JSON padded
 *                              with spaces), the ceiling for an answer of
 *                              that size
 * Prints "listening on http://127.0.0.1:PORT/" and serves until SIGTERM. */
#include <microhttpd.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <arpa/inet.h>
#include <netinet/in.h>

static const char BODY[] =
    "{\"status\":\"ok\",\"version\":\"0.1.0\",\"exercises\":20,\"note\":\"a fixed answer of two hundred "
    "bytes, the size of a small JSON document, for measuring the ceiling of libmicrohttpd here\",\"pad\":\"xx\"}";

static const char *body = BODY;
static size_t body_len = sizeof BODY - 1;

static enum MHD_Result on_request(void *cls, struct MHD_Connection *c, const char *url, const char *method,
                                  const char *version, const char *upload_data, size_t *upload_size,
                                  void **req_cls)
{
    (void)cls, (void)url, (void)method, (void)version, (void)upload_data;
    if (!*req_cls) {                      /* answer on the second call: keep-alive */
        *req_cls = (void *)1;
        return MHD_YES;
    }
    *upload_size = 0;
    struct MHD_Response *r = MHD_create_response_from_buffer(body_len, (void *)(uintptr_t)body, MHD_RESPMEM_PERSISTENT);
    MHD_add_response_header(r, MHD_HTTP_HEADER_CONTENT_TYPE, "application/json");
    enum MHD_Result ret = MHD_queue_response(c, 200, r);
    MHD_destroy_response(r);
    return ret;
}

int main(int argc, char **argv)
{
    int single = argc > 1 && strcmp(argv[1], "single") == 0;
    size_t want = argc > 2 ? strtoul(argv[2], NULL, 10) : 0;
    if (want > body_len && want <= (64u << 20)) {    /* the JSON, then spaces: still one document */
        char *b = malloc(want);
        if (!b)
            return 1;
        memset(b, ' ', want);
        memcpy(b, BODY, body_len);
        body = b, body_len = want;
    }
    struct sockaddr_in addr;
    memset(&addr, 0, sizeof addr);
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    sigset_t stop;
    sigemptyset(&stop);
    sigaddset(&stop, SIGTERM);
    sigaddset(&stop, SIGINT);
    pthread_sigmask(SIG_BLOCK, &stop, NULL);
    struct MHD_Daemon *d = MHD_start_daemon(
        MHD_USE_INTERNAL_POLLING_THREAD | MHD_USE_EPOLL, 0, NULL, NULL, on_request, NULL,
        MHD_OPTION_SOCK_ADDR, (struct sockaddr *)&addr, MHD_OPTION_CONNECTION_LIMIT, (unsigned)4000,
        MHD_OPTION_LISTEN_BACKLOG_SIZE, (unsigned)4096,
        MHD_OPTION_THREAD_POOL_SIZE, (unsigned)(single ? 1 : 2), MHD_OPTION_END);
    if (!d)
        return 1;
    printf("bare_mhd: listening on http://127.0.0.1:%d/ (%s)\n",
           MHD_get_daemon_info(d, MHD_DAEMON_INFO_BIND_PORT)->port, single ? "one thread" : "pool of 2");
    fflush(stdout);
    int sig;
    sigwait(&stop, &sig);
    MHD_stop_daemon(d);
    return 0;
}
