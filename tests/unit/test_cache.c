/* test_cache.c — the response cache (mm_cache.h): bounded in bytes with
 * the least recently used evicted first, entries alive while referenced,
 * answers not to keep served to their waiters and then dropped, identical
 * requests from many threads at once solved once (single flight), the
 * claim of an event thread that solves at once; and the weight that says
 * which exercises the event threads solve themselves (mm_light.h).  Run
 * under ThreadSanitizer by make tsan. */
#include "mm_test.h"

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "mm_cache.h"
#include "mm_light.h"

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

/* ---- a claim: solved at once by a caller that cannot wait ------------------- */

static void woke(void *who) { (*(int *)who)++; }

static void a_claim_should_never_register_its_caller(void **state)
{
    (void)state;
    mm_cache *c = mm_cache_new(1 << 20);
    mm_entry *e, *w, *none = (mm_entry *)1;
    int waiter = 0;
    /* not there: a pending entry with nobody to wake but those who come */
    assert_int_equal(mm_cache_get(c, "k", 1, NULL, &e), MM_CACHE_MISS);
    assert_int_equal(mm_cache_get(c, "k", 1, &waiter, &w), MM_CACHE_WAIT);
    assert_ptr_equal(e, w);
    /* pending: a second claim gets WAIT, no entry and no registration */
    assert_int_equal(mm_cache_get(c, "k", 1, NULL, &none), MM_CACHE_WAIT);
    assert_null(none);
    mm_cache_fill(c, e, 200, text(10, 'x'), 10, NULL, 0, 0, 1, woke);
    assert_int_equal(waiter, 1);                 /* woken once: the claims were not */
    mm_cache_unref(e);
    mm_cache_unref(w);
    /* ready: a claim is a hit */
    assert_int_equal(mm_cache_get(c, "k", 1, NULL, &e), MM_CACHE_HIT);
    assert_int_equal(e->len, 10);
    mm_cache_unref(e);
    mm_cache_stats st;
    mm_cache_get_stats(c, &st);
    assert_int_equal(st.misses, 1);
    assert_int_equal(st.shared, 1);              /* the waiter; the second claim did not wait */
    assert_int_equal(st.hits, 1);
    mm_cache_free(c);
}

/* ---- light exercises (mm_light.h) ---------------------------------------------- */

static int solves_until_light(atomic_int *w, int light_us, long long us)
{
    int n = 0;
    while (!mm_light_now(w, light_us) && n < 100000) {
        mm_light_note(w, us);
        n++;
    }
    return n;
}

static void an_exercise_should_be_light_while_its_solves_average_under_the_bound(void **state)
{
    (void)state;
    atomic_int w;
    atomic_init(&w, mm_light_start(300));
    assert_false(mm_light_now(&w, 300));         /* new: to the workers first */
    /* 16 * 300 (15/16)^n + 10 (1 - (15/16)^n) < 300 from n = 45 on: the
     * integer moves each round down (w - (w - 10) / 16) a little less */
    int n = solves_until_light(&w, 300, 10);
    assert_true(n >= 44 && n <= 46);
    /* settled on 100 us solves, a slow one now and then (a core taken
     * away) keeps it light */
    for (int i = 0; i < 200; i++)
        mm_light_note(&w, 100);
    mm_light_note(&w, 400);
    assert_true(mm_light_now(&w, 300));
    for (int i = 0; i < 40; i++)
        mm_light_note(&w, i % 4 == 0 ? 600 : 150);   /* averages 262 */
    assert_true(mm_light_now(&w, 300));
    /* one solve of 250 ms: back to the workers, for about 60 light ones */
    mm_light_note(&w, 250000);
    assert_false(mm_light_now(&w, 300));
    n = solves_until_light(&w, 300, 10);
    assert_true(n >= 55 && n <= 65);
    /* settled on 10 us solves: one of 16 light_us is enough to send it
     * back; one of 3 is not */
    for (int i = 0; i < 200; i++)
        mm_light_note(&w, 10);
    assert_true(atomic_load(&w) < 10 + 16);      /* whole microseconds: moves under 16 are lost */
    mm_light_note(&w, 3 * 300);
    assert_true(mm_light_now(&w, 300));
    for (int i = 0; i < 200; i++)
        mm_light_note(&w, 10);
    mm_light_note(&w, 16 * 300 + 16 * 25);
    assert_false(mm_light_now(&w, 300));
    /* heavy always: never light */
    for (int i = 0; i < 1000; i++)
        mm_light_note(&w, 2000);
    assert_false(mm_light_now(&w, 300));
    /* light_us 0: nothing is light; a huge bound does not overflow */
    atomic_init(&w, 0);
    assert_false(mm_light_now(&w, 0));
    assert_true(mm_light_start(1000000) == 16000000);
    assert_true(mm_light_start(INT_MAX) > 0);
    mm_light_note(&w, (long long)1 << 40);
    assert_true(atomic_load(&w) > 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_filled_entry_should_be_found_with_its_etag),
        cmocka_unit_test(the_bytes_should_stay_bounded_least_recently_used_first),
        cmocka_unit_test(an_evicted_entry_should_live_while_referenced),
        cmocka_unit_test(an_answer_not_to_keep_should_reach_its_waiters_only),
        cmocka_unit_test(identical_requests_from_many_threads_should_be_solved_once),
        cmocka_unit_test(a_claim_should_never_register_its_caller),
        cmocka_unit_test(an_exercise_should_be_light_while_its_solves_average_under_the_bound),
    };
    return cmocka_run_group_tests_name("cache", tests, NULL, NULL);
}
