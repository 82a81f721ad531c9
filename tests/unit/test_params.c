/* test_params.c — parameter text to values: every kind, every error, and
 * the messages that name the parameter and the valid range. */
#include "mm_test.h"

#include <stdlib.h>
#include <string.h>

#include "mm_params.h"
#include "mm_result_impl.h"

static const char *const bcs[] = {"fixed-free", "fixed-fixed", "free-free", NULL};
static const mm_param P_REAL = {"m", "mass", "kg", MM_REAL, 1, 1e-3, 1e3, .help = "h"};
static const mm_param P_INT = {"n", "count", "", MM_INT, 10, 1, 100, .help = "h"};
static const mm_param P_CHOICE = {"bc", "ends", "", MM_CHOICE, 0, 0, 0, .choices = bcs, .help = "h"};
static const mm_param P_VEC = {"b", "rhs", "", MM_VECTOR, 0, -1e6, 1e6, "10,0,1000", .max_cols = 5, .help = "h"};
static const mm_param P_MAT = {"A", "matrix", "", MM_MATRIX, 0, -1e6, 1e6, "1,2,3;4,5,6;7,8,10",
                               .max_rows = 4, .max_cols = 4, .help = "h"};
static const mm_param P_EXPR = {"f", "function", "", MM_EXPR, 0, 0, 0, "x^2-2", .vars = "x", .help = "h"};

static int parse(const mm_param *p, const char *text, mm_value *v, mm_error *err, mm_result *r)
{
    return mm_param_parse(p, text, strlen(text), v, r, err);
}

static void reals_should_accept_numbers_and_constant_expressions(void **state)
{
    (void)state;
    mm_result r;
    mm_result_init(&r, 1 << 20);
    mm_value v;
    mm_error err;
    assert_int_equal(parse(&P_REAL, " 2.5 ", &v, &err, &r), MM_OK);
    assert_true(v.x == 2.5);
    assert_int_equal(parse(&P_REAL, "1e2", &v, &err, &r), MM_OK);
    assert_true(v.x == 100);
    assert_int_equal(parse(&P_REAL, "pi/2", &v, &err, &r), MM_OK);
    check_rel(v.x, M_PI / 2, 1e-15, "pi/2");
    assert_int_equal(parse(&P_REAL, "2*sqrt(4)", &v, &err, &r), MM_OK);
    assert_true(v.x == 4);
    mm_result_release(&r);
}

static void reals_should_refuse_bad_text_naming_the_parameter(void **state)
{
    (void)state;
    mm_result r;
    mm_result_init(&r, 1 << 20);
    mm_value v;
    mm_error err;
    const char *bad[] = {"abc", "", "nan", "inf", "-inf", "1/0", "0x10p", "1,2", "1e", "--1"};
    for (unsigned i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        int rc = parse(&P_REAL, bad[i], &v, &err, &r);
        if (rc != MM_EVALUE)
            fail_msg("'%s' gave %d (%s)", bad[i], rc, err.msg);
        assert_string_equal(err.param, "m");
    }
    assert_int_equal(parse(&P_REAL, "-1", &v, &err, &r), MM_ERANGE);
    assert_string_equal(err.param, "m");
    assert_non_null(strstr(err.msg, "between 0.001 and 1000 kg"));
    assert_non_null(strstr(err.msg, "got -1"));
    assert_int_equal(parse(&P_REAL, "1e999", &v, &err, &r), MM_ERANGE);
    assert_int_equal(mm_param_parse(&P_REAL, "1\0" "2", 3, &v, &r, &err), MM_EVALUE);
    mm_result_release(&r);
}

static void integers_and_choices_should_be_exact(void **state)
{
    (void)state;
    mm_result r;
    mm_result_init(&r, 1 << 20);
    mm_value v;
    mm_error err;
    assert_int_equal(parse(&P_INT, "42", &v, &err, &r), MM_OK);
    assert_true(v.x == 42);
    assert_int_equal(parse(&P_INT, "4.5", &v, &err, &r), MM_EVALUE);
    assert_int_equal(parse(&P_INT, "0", &v, &err, &r), MM_ERANGE);
    assert_int_equal(parse(&P_CHOICE, "free-free", &v, &err, &r), MM_OK);
    assert_true(v.x == 2);
    assert_string_equal(v.text, "free-free");
    assert_int_equal(parse(&P_CHOICE, "pinned", &v, &err, &r), MM_EVALUE);
    assert_non_null(strstr(err.msg, "fixed-free, fixed-fixed, free-free"));
    mm_result_release(&r);
}

static void vectors_and_matrices_should_read_matlab_text(void **state)
{
    (void)state;
    mm_result r;
    mm_result_init(&r, 1 << 20);
    mm_value v;
    mm_error err;
    assert_int_equal(parse(&P_VEC, "[10;0;1000]", &v, &err, &r), MM_OK);
    assert_int_equal(v.cols, 3);
    assert_true(v.data[2] == 1000);
    assert_int_equal(parse(&P_VEC, "1 2, 3", &v, &err, &r), MM_OK);
    assert_int_equal(v.cols, 3);
    assert_int_equal(parse(&P_MAT, "1,2,3;4,5,6;7,8,10", &v, &err, &r), MM_OK);
    assert_int_equal(v.rows, 3);
    assert_int_equal(v.cols, 3);
    assert_true(v.data[8] == 10);
    assert_int_equal(parse(&P_MAT, "1 2\n3 4\n", &v, &err, &r), MM_OK);
    assert_int_equal(v.rows, 2);
    assert_int_equal(parse(&P_MAT, "pi,1;2,3", &v, &err, &r), MM_OK);
    check_rel(v.data[0], M_PI, 1e-15, "pi in a matrix");

    assert_int_equal(parse(&P_MAT, "1,2;3", &v, &err, &r), MM_EVALUE);   /* ragged */
    assert_non_null(strstr(err.msg, "row 2"));
    assert_int_equal(parse(&P_MAT, "1;2;3;4;5", &v, &err, &r), MM_ERANGE);
    assert_int_equal(parse(&P_VEC, "1,2,3,4,5,6", &v, &err, &r), MM_ERANGE);
    assert_int_equal(parse(&P_VEC, "1,x,3", &v, &err, &r), MM_EVALUE);
    assert_non_null(strstr(err.msg, "b(2)"));
    assert_int_equal(parse(&P_VEC, "1,2e7", &v, &err, &r), MM_ERANGE);
    assert_int_equal(parse(&P_VEC, "", &v, &err, &r), MM_EVALUE);
    assert_int_equal(parse(&P_MAT, "1,2;;3,4", &v, &err, &r), MM_EVALUE);
    /* only separators (found by fuzz_params): no numbers at all */
    assert_int_equal(parse(&P_MAT, ",", &v, &err, &r), MM_EVALUE);
    assert_int_equal(parse(&P_MAT, " ; ;", &v, &err, &r), MM_EVALUE);
    assert_int_equal(parse(&P_VEC, ",,", &v, &err, &r), MM_EVALUE);
    assert_int_equal(parse(&P_VEC, "[]", &v, &err, &r), MM_EVALUE);
    mm_result_release(&r);
}

static void a_huge_matrix_should_be_refused_before_allocation(void **state)
{
    (void)state;
    mm_result r;
    mm_result_init(&r, 1 << 16);   /* 64 KiB: a million numbers would not fit */
    size_t n = 1000 * 1000;
    char *text = malloc(2 * n + 1);
    for (size_t i = 0; i < n; i++) {
        text[2 * i] = '1';
        text[2 * i + 1] = (i + 1) % 1000 ? ',' : ';';
    }
    text[2 * n] = '\0';
    mm_value v;
    mm_error err;
    int rc = mm_param_parse(&P_MAT, text, MM_PARAM_TEXT_MAX, &v, &r, &err);
    assert_int_equal(rc, MM_ERANGE);
    assert_false(r.over_cap);
    rc = mm_param_parse(&P_MAT, text, 2 * n, &v, &r, &err);
    assert_int_equal(rc, MM_ERANGE);   /* over the text limit */
    free(text);
    mm_result_release(&r);
}

static void expressions_should_be_kept_as_text_with_a_length_limit(void **state)
{
    (void)state;
    mm_result r;
    mm_result_init(&r, 1 << 20);
    mm_value v;
    mm_error err;
    assert_int_equal(parse(&P_EXPR, " x^3+sin(x)-2 ", &v, &err, &r), MM_OK);
    assert_string_equal(v.text, "x^3+sin(x)-2");
    char big[600];
    memset(big, 'x', sizeof big - 1);
    big[sizeof big - 1] = '\0';
    assert_int_equal(parse(&P_EXPR, big, &v, &err, &r), MM_ERANGE);
    mm_result_release(&r);
}

static void defaults_should_parse(void **state)
{
    (void)state;
    mm_result r;
    mm_result_init(&r, 1 << 20);
    mm_value v;
    mm_error err;
    assert_int_equal(mm_param_default(&P_MAT, &v, &r, &err), MM_OK);
    assert_int_equal(v.rows * v.cols, 9);
    assert_int_equal(mm_param_default(&P_CHOICE, &v, &r, &err), MM_OK);
    assert_string_equal(v.text, "fixed-free");
    mm_result_release(&r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(reals_should_accept_numbers_and_constant_expressions),
        cmocka_unit_test(reals_should_refuse_bad_text_naming_the_parameter),
        cmocka_unit_test(integers_and_choices_should_be_exact),
        cmocka_unit_test(vectors_and_matrices_should_read_matlab_text),
        cmocka_unit_test(a_huge_matrix_should_be_refused_before_allocation),
        cmocka_unit_test(expressions_should_be_kept_as_text_with_a_length_limit),
        cmocka_unit_test(defaults_should_parse),
    };
    return cmocka_run_group_tests_name("params", tests, NULL, NULL);
}
