/* mm_light.h — which solves the event threads make themselves.
 *
 * A solve that is not in the cache costs a worker's wake-up, the
 * connection's suspension and its resumption: two thread switches and an
 * eventfd, about 55 us of server CPU on this machine's virtual cores, eight
 * times num-complex's whole solve (7 us).  So an exercise is solved on the
 * event thread that read the request, and answered at once, while its
 * weight is under light_us (300 us by default): the CPU time its solves
 * took to solve, write and compress, averaged over about its last 16 (each
 * solve moves the weight 1/16 of the way to its own).  CPU time and an
 * average, not the wall time of the last solve: on a shared machine a
 * 100 us solve now and then counts 300-400 us, its virtual core taken away
 * meanwhile.
 *
 * One solve of more than 16 light_us (4.8 ms: a student who asks for 4,000
 * points or a long integration, up to the exercise's limits, 250 ms) lifts
 * the weight over light_us by itself, and the exercise's next solves go to
 * the workers until the average has come down again (about 60 light ones
 * after a 250 ms solve).  So an event thread is held by at most one heavy
 * solve in every ~60 of an exercise that is heavy only sometimes, never by
 * one that is heavy always, and briefly (under 16 light_us) by the rest.
 * An exercise starts at 16 light_us: its first ~45 solves go to the
 * workers, which weigh them.
 *
 * The weight is one int per exercise, in whole microseconds (a move under
 * 1 us is lost: it settles within 15 us of a steady solve's time), read and
 * moved without a lock: two threads moving it at once lose one move, which
 * does no harm.
 */
#ifndef MM_LIGHT_H
#define MM_LIGHT_H

#include <limits.h>
#include <stdatomic.h>

#define MM_LIGHT_US 300            /* the default light_us */

/* the weight an exercise starts with */
static inline int mm_light_start(int light_us) { return light_us > INT_MAX / 32 ? INT_MAX / 2 : 16 * light_us; }

/* is the exercise of this weight light?  (light_us <= 0: none is) */
static inline int mm_light_now(const atomic_int *weight, int light_us)
{
    return light_us > 0 && weight && atomic_load_explicit(weight, memory_order_relaxed) < light_us;
}

/* a solve of us microseconds of CPU: the weight moved 1/16 of the way to it */
static inline void mm_light_note(atomic_int *weight, long long us)
{
    if (!weight)
        return;
    long long w = atomic_load_explicit(weight, memory_order_relaxed);
    w += (us - w) / 16;
    atomic_store_explicit(weight, (int)(w < 0 ? 0 : w > INT_MAX / 2 ? INT_MAX / 2 : w), memory_order_relaxed);
}

#endif
