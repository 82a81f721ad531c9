/* test_json.c — the JSON writer and the shortest number form, checked by
 * reading the output back with cJSON and strtod (independent parsers). */
#include "mm_test.h"

#include <cJSON.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mm_dtoa.h"
#include "mm_json.h"

/* mm_dtoa's fast path for short decimals (m 10^-k) must write what {fmt}'s
 * Dragonbox writes, character for character: short decimals of every
 * length and sign near the fast path's edges (1e-4, 4.5e9), and random
 * doubles that only look close to one. */
static void short_decimals_should_be_written_as_dragonbox_writes_them(void **state)
{
    (void)state;
    char fast[MM_DTOA_BUFSIZE], ref[MM_DTOA_BUFSIZE];
    static const double edge[] = {1e-4, 9.9999999999999991e-05, 0.00012, 0.0195, 0.07, 0.3, 0.30000000000000004,
                                  1.5, 100, 1e6, 4.4e9, 4.5e9, 4.6e9, 123456.789, 8.000000001, -0.5, -1e-4};
    for (size_t i = 0; i < sizeof edge / sizeof edge[0]; i++) {
        mm_dtoa(edge[i], fast);
        mm_dtoa_fmt(edge[i], ref);
        if (strcmp(fast, ref) != 0)
            fail_msg("%.17g: %s, Dragonbox %s", edge[i], fast, ref);
    }
    unsigned long long x = 88172645463325252ULL;
    static const double p10[] = {1, 10, 100, 1e3, 1e4, 1e5, 1e6, 1e7};
    for (int i = 0; i < 2000000; i++) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;           /* xorshift64 */
        long long m = (long long)((x >> 8) % 100000000000ULL) >> (x % 40);
        double v = (x & 0x100000 ? -1 : 1) * (double)m / p10[x % 8];
        if (i % 3 == 0)
            v = (double)m * (1 / p10[x % 8]);              /* near a short decimal, often not one */
        mm_dtoa(v, fast);
        mm_dtoa_fmt(v, ref);
        if (strcmp(fast, ref) != 0)
            fail_msg("%.17g: %s, Dragonbox %s", v, fast, ref);
    }
}

static void numbers_should_read_back_exactly_in_the_shortest_form(void **state)
{
    (void)state;
    char buf[MM_DTOA_BUFSIZE];
    mm_dtoa(0.1, buf);
    assert_string_equal(buf, "0.1");
    mm_dtoa(100.0, buf);
    assert_string_equal(buf, "100");
    mm_dtoa(-0.0, buf);
    assert_string_equal(buf, "0");
    mm_dtoa(1e21, buf);
    assert_string_equal(buf, "1e+21");
    mm_dtoa(1.0 / 3.0, buf);
    assert_string_equal(buf, "0.3333333333333333");
    /* a million pseudo-random doubles of every magnitude round-trip */
    unsigned long long x = 88172645463325252ULL;
    for (int i = 0; i < 1000000; i++) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;           /* xorshift64 */
        double v;
        unsigned long long bits = x & ~(0x7ffULL << 52);
        bits |= (unsigned long long)(x % 2046 + 1) << 52;   /* finite exponents only */
        memcpy(&v, &bits, sizeof v);
        int n = mm_dtoa(v, buf);
        assert_true(n > 0 && n < MM_DTOA_BUFSIZE);
        if (strtod(buf, NULL) != v)
            fail_msg("%.17g printed as %s", v, buf);
        if (i < 100000) {              /* shortest: no fewer digits round-trip */
            int digits = 0, lead = 1;
            for (const char *c = buf; *c && *c != 'e'; c++) {
                if (*c >= '1' && *c <= '9')
                    lead = 0;
                if (*c >= '0' && *c <= '9' && !lead)
                    digits++;
            }
            if (!strchr(buf, '.') && !strchr(buf, 'e'))   /* integer: trailing zeros are places */
                for (size_t k = strlen(buf); k > 1 && buf[k - 1] == '0'; k--)
                    digits--;
            char tmp[40];
            for (int p = 1; p < 17; p++) {
                snprintf(tmp, sizeof tmp, "%.*g", p, v);
                if (strtod(tmp, NULL) == v) {
                    if (p < digits)
                        fail_msg("%.17g: %s has %d digits but %s (%d) round-trips", v, buf,
                                 digits, tmp, p);
                    break;
                }
            }
        }
    }
}

static void strings_should_be_escaped_into_valid_json(void **state)
{
    (void)state;
    mm_buf b;
    mm_buf_init(&b, 1 << 20);
    const char nasty[] = "quote\" back\\ nl\n tab\t ctl\x01 bad\xff\xfe utf8 \xc3\xa9 overlong \xc0\xaf";
    mm_buf_puts(&b, "{\"s\":");
    mm_buf_strn(&b, nasty, sizeof nasty - 1);
    mm_buf_puts(&b, ",\"n\":");
    mm_buf_num(&b, 2.5, "n");
    mm_buf_char(&b, '}');
    cJSON *j = cJSON_Parse(b.p);
    assert_non_null(j);
    const char *s = cJSON_GetObjectItem(j, "s")->valuestring;
    assert_non_null(strstr(s, "quote\" back\\ nl\n tab\t ctl\x01 bad"));
    assert_non_null(strstr(s, "\xc3\xa9"));                 /* valid UTF-8 kept */
    assert_null(strstr(s, "\xff"));                         /* invalid replaced */
    assert_null(strstr(s, "\xc0\xaf"));                     /* overlong replaced */
    assert_true(cJSON_GetObjectItem(j, "n")->valuedouble == 2.5);
    cJSON_Delete(j);
    mm_buf_free(&b);
}

static void a_nonfinite_number_should_be_flagged_not_written(void **state)
{
    (void)state;
    mm_buf b;
    mm_buf_init(&b, 1 << 20);
    mm_buf_num(&b, 1.0, "a");
    assert_false(b.nonfinite);
    mm_buf_num(&b, NAN, "series x");
    mm_buf_num(&b, INFINITY, "later");
    assert_true(b.nonfinite);
    assert_string_equal(b.where, "series x");
    assert_null(strstr(b.p, "nan"));
    assert_null(strstr(b.p, "inf"));
    mm_buf_free(&b);
}

static void the_buffer_should_stop_at_its_limit(void **state)
{
    (void)state;
    mm_buf b;
    mm_buf_init(&b, 100);
    for (int i = 0; i < 50; i++)
        mm_buf_puts(&b, "0123456789");
    assert_true(b.failed);
    assert_true(b.len < 100);
    mm_buf_free(&b);
}

/* The numbers an animation is made of: coordinates rounded to q decimals
 * (nearbyint(x 10^q) / 10^q, as mm_exhelp's round_shape makes them) of
 * every size the fast path sees, and their neighbours one ulp away (which
 * are not short): written as Dragonbox writes them, and read back. */
static void rounded_coordinates_should_be_written_as_dragonbox_writes_them(void **state)
{
    (void)state;
    char fast[MM_DTOA_BUFSIZE], ref[MM_DTOA_BUFSIZE];
    unsigned long long x = 0x9E3779B97F4A7C15ULL;
    long short_ones = 0;
    for (int i = 0; i < 3000000; i++) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;           /* xorshift64 */
        int q = (int)(x % 8);                              /* 0..7 decimals: 7 is past the fast path */
        double p = 1;
        for (int k = 0; k < q; k++)
            p *= 10;
        double y = ldexp((double)(x >> 11), -53) * pow(10, (int)((x >> 3) % 14) - 5);   /* 1e-5 .. 1e9 */
        double v = nearbyint(y * p) / p;
        if (x & 0x10000)
            v = -v;
        if (i % 5 == 0)
            v = nextafter(v, 0);
        int n = mm_dtoa(v, fast);
        mm_dtoa_fmt(v, ref);
        if (strcmp(fast, ref) != 0)
            fail_msg("%.17g: %s, Dragonbox %s", v, fast, ref);
        if (strtod(fast, NULL) != (v == 0 ? 0 : v))
            fail_msg("%.17g printed as %s", v, fast);
        short_ones += n <= 8;
    }
    assert_true(short_ones > 1000000);                    /* the fast path was exercised */
}

/* mm_dtoa lays out Dragonbox's digits itself (fixed or exponent notation,
 * the point inside, before or after the digits): it must write what
 * {fmt}'s own "{}" writes for every finite double.  Random bit patterns
 * (every exponent, subnormals included), every power of two and ten and
 * their neighbours, integers around 2^53, the switch points of the layout
 * (1e-5 / 1e-4: exponent below -4; 1e16: exponent 16 or more), the fast
 * path's edges (1e-4, 4.5e9, 2^32 10^-6 steps) and decimals of 1 to 17
 * digits at every scale. */
static uint64_t next_bits(uint64_t *x)
{
    *x ^= *x << 13, *x ^= *x >> 7, *x ^= *x << 17;         /* xorshift64 */
    return *x;
}

static long compare_with_fmt(double v, long *bad)
{
    char fast[MM_DTOA_BUFSIZE], ref[MM_DTOA_BUFSIZE];
    int n = mm_dtoa(v, fast);
    mm_dtoa_fmt(v, ref);
    if ((strcmp(fast, ref) != 0 || n != (int)strlen(ref)) && (*bad)++ < 10)
        print_message("%.17g (%a): %s, {fmt} %s\n", v, v, fast, ref);
    return 1;
}

static void every_double_should_be_laid_out_as_fmt_lays_it_out(void **state)
{
    (void)state;
    long bad = 0, n = 0;
    uint64_t x = 0x2545F4914F6CDD1DULL;
    for (int i = 0; i < 1500000; i++) {                   /* any bits */
        uint64_t bits = next_bits(&x);
        double v;
        memcpy(&v, &bits, sizeof v);
        if (isfinite(v))
            n += compare_with_fmt(v, &bad);
    }
    for (int e = -1075; e < 1024; e++) {                   /* powers of two, neighbours */
        double v = ldexp(1, e);
        n += compare_with_fmt(v, &bad) + compare_with_fmt(-v, &bad);
        n += compare_with_fmt(nextafter(v, 0), &bad) + compare_with_fmt(nextafter(v, INFINITY), &bad);
    }
    for (int e = -325; e <= 308; e++) {                    /* powers of ten, neighbours, multiples */
        double p = pow(10, e);
        for (int k = 1; k < 20; k++)
            n += compare_with_fmt(k * p, &bad) + compare_with_fmt(-k * p, &bad);
        double up = p, down = p;
        for (int k = 0; k < 3; k++) {
            up = nextafter(up, INFINITY), down = nextafter(down, 0);
            n += compare_with_fmt(up, &bad) + compare_with_fmt(down, &bad);
        }
    }
    static const double edge[] = {1e-5, 9.999999999999999e-06, 1.0000000000000001e-05, 1e-4,
                                  9.9999999999999991e-05, 1.0000000000000002e-04, 1e15, 1e16,
                                  9999999999999998, 1.0000000000000002e16, 123456789012345678.0,
                                  4.5e9, 4294967296e-6, 4294.967296, 4294967295.999999, 4499999999.999999,
                                  5e-324, 2.2250738585072014e-308, 1.7976931348623157e308,
                                  0.1, 0.2, 0.30000000000000004, 1.0 / 3.0, 2.0 / 3.0, -0.0, 0.0};
    for (size_t i = 0; i < sizeof edge / sizeof edge[0]; i++)
        n += compare_with_fmt(edge[i], &bad) + compare_with_fmt(-edge[i], &bad);
    for (long long i = -30000; i <= 30000; i++) {          /* integers near 0 and 2^53 */
        n += compare_with_fmt((double)i, &bad);
        n += compare_with_fmt((double)((1LL << 53) + i), &bad);
        n += compare_with_fmt((double)((1LL << 53) + i) * 1e-6, &bad);   /* near the fast path's top */
        n += compare_with_fmt((double)i * 1e-7, &bad);                  /* 1e-7 steps: fast path and not */
    }
    static const double p10[] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10,
                                 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18};
    for (int i = 0; i < 1500000; i++) {                   /* d digits at scale 10^s */
        uint64_t r = next_bits(&x);
        int d = 1 + (int)(r % 17), sc = (int)((r >> 5) % 19);
        long long m = (long long)((r >> 11) % (uint64_t)p10[d]);
        double v = (r >> 10 & 1) ? (double)m / p10[sc] : (double)m * p10[sc] * 1e-20 * 1e12;
        if (r >> 9 & 1)
            v = -v;
        n += compare_with_fmt(v, &bad);
    }
    print_message("%ld doubles, %ld written otherwise than {fmt} writes them\n", n, bad);
    assert_int_equal(bad, 0);
}

/* An animation's coordinates are written one frame a row: mm_buf_rows
 * gives what the rows one by one give, brackets and commas between, empty
 * rows and a missing array included, flags a non-finite number, and fails
 * near the buffer's limit where mm_buf_nums would. */
static void rows_should_be_written_as_their_arrays_one_by_one(void **state)
{
    (void)state;
    double v[6 * 7];
    for (int i = 0; i < 42; i++)
        v[i] = i % 3 ? round(i * 1234.5) / 1e4 : -1.0 / (i + 7);
    for (size_t cols = 0; cols <= 7; cols += 7) {
        for (size_t max = 64; max < 2000; max += 37) {
            mm_buf a, b;
            mm_buf_init(&a, max);
            mm_buf_init(&b, max);
            mm_buf_puts(&a, "x:");
            mm_buf_puts(&b, "x:");
            mm_buf_rows(&a, v, 6, cols, "r");
            mm_buf_char(&b, '[');
            for (size_t r = 0; r < 6; r++) {
                if (r)
                    mm_buf_char(&b, ',');
                mm_buf_nums(&b, v + r * cols, cols, "r");
            }
            mm_buf_char(&b, ']');
            assert_int_equal(a.failed, b.failed);
            if (!a.failed) {
                assert_int_equal(a.len, b.len);
                assert_string_equal(a.p, b.p);
            }
            mm_buf_free(&a);
            mm_buf_free(&b);
        }
    }
    mm_buf a;
    mm_buf_init(&a, 1 << 16);
    mm_buf_rows(&a, v, 0, 7, "r");
    assert_string_equal(a.p, "[]");
    mm_buf_reset(&a);
    v[9] = NAN;
    mm_buf_rows(&a, v, 6, 7, "rows");
    assert_true(a.nonfinite);
    assert_string_equal(a.where, "rows");
    cJSON *j = cJSON_Parse(a.p);
    assert_non_null(j);
    assert_int_equal(cJSON_GetArraySize(j), 6);
    assert_int_equal(cJSON_GetArraySize(cJSON_GetArrayItem(j, 1)), 7);
    cJSON_Delete(j);
    mm_buf_free(&a);
}

/* mm_buf_nums writes an array as mm_buf_num writes its numbers one by one,
 * commas between, non-finite numbers flagged (the first's owner kept); and
 * near the buffer's limit it fails where they would. */
static void an_array_should_be_written_as_its_numbers_one_by_one(void **state)
{
    (void)state;
    double v[700];
    for (int i = 0; i < 700; i++)
        v[i] = i % 7 == 0 ? i * 0.02 : i % 7 == 1 ? -1.0 / (i + 3) : i % 7 == 2 ? 1e300 / (i + 1) : round(i * 13.7) / 100;
    mm_buf a, b;
    mm_buf_init(&a, 1 << 20);
    mm_buf_init(&b, 1 << 20);
    mm_buf_nums(&a, v, 700, "v");
    mm_buf_char(&b, '[');
    for (int i = 0; i < 700; i++) {
        if (i)
            mm_buf_char(&b, ',');
        mm_buf_num(&b, v[i], "v");
    }
    mm_buf_char(&b, ']');
    assert_int_equal(a.len, b.len);
    assert_string_equal(a.p, b.p);
    assert_int_equal(strlen(a.p), a.len);
    mm_buf_reset(&a);
    mm_buf_nums(&a, v, 0, "none");
    assert_string_equal(a.p, "[]");
    v[3] = NAN, v[500] = INFINITY;
    mm_buf_reset(&a);
    mm_buf_nums(&a, v, 700, "series y");
    assert_true(a.nonfinite);
    assert_string_equal(a.where, "series y");
    assert_null(strstr(a.p, "nan"));
    cJSON *j = cJSON_Parse(a.p);
    assert_non_null(j);
    assert_int_equal(cJSON_GetArraySize(j), 700);
    cJSON_Delete(j);
    mm_buf_free(&a);
    mm_buf_free(&b);
    /* a buffer that holds part of the array: failed, as one at a time */
    for (size_t max = 200; max < 9000; max += 997) {
        mm_buf_init(&a, max);
        mm_buf_init(&b, max);
        mm_buf_nums(&a, v + 4, 400, "v");
        mm_buf_char(&b, '[');
        for (int i = 4; i < 404; i++) {
            if (i > 4)
                mm_buf_char(&b, ',');
            mm_buf_num(&b, v[i], "v");
        }
        mm_buf_char(&b, ']');
        assert_int_equal(a.failed, b.failed);
        assert_true(a.len < max);
        mm_buf_free(&a);
        mm_buf_free(&b);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(short_decimals_should_be_written_as_dragonbox_writes_them),
        cmocka_unit_test(numbers_should_read_back_exactly_in_the_shortest_form),
        cmocka_unit_test(rounded_coordinates_should_be_written_as_dragonbox_writes_them),
        cmocka_unit_test(every_double_should_be_laid_out_as_fmt_lays_it_out),
        cmocka_unit_test(an_array_should_be_written_as_its_numbers_one_by_one),
        cmocka_unit_test(rows_should_be_written_as_their_arrays_one_by_one),
        cmocka_unit_test(strings_should_be_escaped_into_valid_json),
        cmocka_unit_test(a_nonfinite_number_should_be_flagged_not_written),
        cmocka_unit_test(the_buffer_should_stop_at_its_limit),
    };
    return cmocka_run_group_tests_name("json", tests, NULL, NULL);
}
