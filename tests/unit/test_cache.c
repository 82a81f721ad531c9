/* test_cache.c — the response cache (mm_cache.h): bounded in bytes with
 * the least recently used evicted first, entries alive while referenced,
 * answers not to keep served to their waiters and then dropped, and
 * identical requests from many threads at once solved once (single
 * flight).  Run under ThreadSanitizer by make tsan. */
#include "mm_test.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "mm_cache.h"

static char *text(size_t n, char c)
{
    char *s = malloc(n + 1);
    memset(s, c, n);
    s[n] = '\0';
    return s;
}

/* get a key and fill it at once with n bytes; returns the entry (ref'd) */
static mm_entry *put(mm_cache *c, const char *key, size_t n, int keep)
{
    mm_entry *e;
    int who;
    assert_int_equal(mm_cache_get(c, key, strlen(key), &who, &e), MM_CACHE_MISS);
    mm_cache_fill(c, e, 200, text(n, 'x'), n, NULL, 0, 5, keep, NULL);
    return e;
}

static void a_filled_entry_should_be_found_with_its_etag(void **state)
{
    (void)state;
    mm_cache *c = mm_cache_new(1 << 20);
    mm_entry *e = put(c, "ex?a=1", 100, 1);
    mm_cache_unref(e);
    mm_entry *f = mm_cache_lookup(c, "ex?a=1", 6);
    assert_non_null(f);
    assert_int_equal(f->status, 200);
    assert_int_equal(f->len, 100);
    char etag[MM_ETAG_SIZE];
    mm_api_answer_etag("ex?a=1", 6, etag);
    assert_string_equal(f->etag, etag);
    assert_int_equal(f->solve_us, 5);
    mm_cache_unref(f);
    assert_null(mm_cache_lookup(c, "ex?a=2", 6));
    assert_null(mm_cache_lookup(c, "ex?a=", 5));
    mm_cache_stats st;
    mm_cache_get_stats(c, &st);
    assert_int_equal(st.entries, 1);
    assert_int_equal(st.hits, 1);
    assert_int_equal(st.misses, 1);
    mm_cache_free(c);
}

static void the_bytes_should_stay_bounded_least_recently_used_first(void **state)
{
    (void)state;
    mm_cache *c = mm_cache_new(10000);
    char key[32];
    for (int i = 0; i < 100; i++) {
        snprintf(key, sizeof key, "k%d", i);
        mm_cache_unref(put(c, key, 1000, 1));
        mm_entry *keep = mm_cache_lookup(c, "k0", 2);   /* k0 stays in use */
        if (keep)
            mm_cache_unref(keep);
        mm_cache_stats st;
        mm_cache_get_stats(c, &st);
        assert_true(st.bytes <= 10000);
    }
    mm_entry *k0 = mm_cache_lookup(c, "k0", 2), *k1 = mm_cache_lookup(c, "k1", 2);
    assert_non_null(k0);                                 /* recently used: kept */
    assert_null(k1);                                     /* not: evicted */
    mm_cache_unref(k0);
    mm_cache_stats st;
    mm_cache_get_stats(c, &st);
    assert_true(st.evictions > 80);
    mm_cache_free(c);
}

static void an_evicted_entry_should_live_while_referenced(void **state)
{
    (void)state;
    mm_cache *c = mm_cache_new(3000);
    mm_entry *a = put(c, "a", 1000, 1);                  /* our reference kept */
    mm_cache_unref(put(c, "b", 1000, 1));
    mm_cache_unref(put(c, "c", 1000, 1));
    assert_null(mm_cache_lookup(c, "a", 1));             /* evicted... */
    assert_int_equal(a->len, 1000);                      /* ...but still whole */
    assert_true(a->body[999] == 'x');
    mm_cache_unref(a);
    mm_cache_free(c);
}

static void an_answer_not_to_keep_should_reach_its_waiters_only(void **state)
{
    (void)state;
    mm_cache *c = mm_cache_new(1 << 20);
    mm_entry *e, *w;
    int a, b;
    assert_int_equal(mm_cache_get(c, "k", 1, &a, &e), MM_CACHE_MISS);
    assert_int_equal(mm_cache_get(c, "k", 1, &b, &w), MM_CACHE_WAIT);
    assert_ptr_equal(e, w);
    mm_cache_fill(c, e, 500, text(10, 'e'), 10, NULL, 0, 0, 0, NULL);
    assert_int_equal(w->status, 500);
    assert_null(mm_cache_lookup(c, "k", 1));
    mm_cache_unref(e);
    mm_cache_unref(w);
    assert_int_equal(mm_cache_get(c, "k", 1, &a, &e), MM_CACHE_MISS);   /* asked again: solved again */
    mm_cache_fill(c, e, 200, text(10, 'x'), 10, NULL, 0, 0, 1, NULL);
    mm_cache_unref(e);
    mm_cache_free(c);
}

/* ---- single flight ---------------------------------------------------------- */

typedef struct flight {
    mm_cache *c;
    atomic_int solved, woken;
    pthread_mutex_t lock;
    pthread_cond_t cond;
} flight;

typedef struct rider {
    flight *f;
    int done;
    size_t len;
} rider;

static void wake_rider(void *who)
{
    rider *r = who;
    pthread_mutex_lock(&r->f->lock);
    r->done = 1;
    atomic_fetch_add(&r->f->woken, 1);
    pthread_cond_broadcast(&r->f->cond);
    pthread_mutex_unlock(&r->f->lock);
}

static void *ride(void *arg)
{
    rider *r = arg;
    flight *f = r->f;
    mm_entry *e;
    int rc = mm_cache_get(f->c, "same", 4, r, &e);
    if (rc == MM_CACHE_MISS) {
        atomic_fetch_add(&f->solved, 1);
        mm_cache_fill(f->c, e, 200, text(4096, 's'), 4096, NULL, 0, 1, 1, wake_rider);
    } else if (rc == MM_CACHE_HIT) {
        wake_rider(r);
    }
    pthread_mutex_lock(&f->lock);
    while (!r->done)
        pthread_cond_wait(&f->cond, &f->lock);
    pthread_mutex_unlock(&f->lock);
    r->len = e->len;                                     /* ready: seen after the wake */
    mm_cache_unref(e);
    return NULL;
}

static void identical_requests_from_many_threads_should_be_solved_once(void **state)
{
    (void)state;
    enum { T = 32 };
    flight f = {.c = mm_cache_new(1 << 20)};
    pthread_mutex_init(&f.lock, NULL);
    pthread_cond_init(&f.cond, NULL);
    pthread_t th[T];
    rider r[T];
    for (int i = 0; i < T; i++) {
        r[i] = (rider){&f, 0, 0};
        pthread_create(&th[i], NULL, ride, &r[i]);
    }
    for (int i = 0; i < T; i++)
        pthread_join(th[i], NULL);
    assert_int_equal(atomic_load(&f.solved), 1);
    assert_int_equal(atomic_load(&f.woken), T);
    for (int i = 0; i < T; i++)
        assert_int_equal(r[i].len, 4096);
    mm_cache_stats st;
    mm_cache_get_stats(f.c, &st);
    assert_int_equal(st.misses, 1);
    assert_int_equal(st.hits + st.shared, T - 1);
    pthread_mutex_destroy(&f.lock);
    pthread_cond_destroy(&f.cond);
    mm_cache_free(f.c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_filled_entry_should_be_found_with_its_etag),
        cmocka_unit_test(the_bytes_should_stay_bounded_least_recently_used_first),
        cmocka_unit_test(an_evicted_entry_should_live_while_referenced),
        cmocka_unit_test(an_answer_not_to_keep_should_reach_its_waiters_only),
        cmocka_unit_test(identical_requests_from_many_threads_should_be_solved_once),
    };
    return cmocka_run_group_tests_name("cache", tests, NULL, NULL);
}
