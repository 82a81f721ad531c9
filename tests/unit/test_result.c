/* test_result.c — the answer builder of mm_exercise.h: declared outputs,
 * families, accuracy, animation, and failures that stick. */
#include "mm_test.h"

#include <cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mm_api.h"
#include "mm_exhelp.h"
#include "mm_result_impl.h"

static const char *const cols[] = {"k", "value", NULL}, *const units[] = {"", "m", NULL};
static const char *const methods[] = {"euler", "rk4", NULL};
enum { O_A, O_X, O_CURVE, O_ERR, O_T, O_ANIM };
static const mm_output outputs[] = {
    [O_A] = MM_SCALAR("a", "the a", "m", .flags = MM_ANSWER | MM_EXACT),
    [O_X] = MM_SCALAR("x%d", "component %d of x", "", .first = 1, .last = 3),
    [O_CURVE] = MM_SERIES("y_%s", "y by %s", "m", "t", "s", .keys = methods, .figure = "y",
                          .role = "reference"),
    [O_ERR] = MM_SCALAR("err", "an estimate", "m"),
    [O_T] = MM_TABLE("t", "a table", cols, units),
    [O_ANIM] = MM_ANIMATION("a moving thing"),
};

static int solve_demo(const mm_value *in, mm_result *res, mm_error *err)
{
    (void)in, (void)err;
    mm_res_scalar(res, O_A, 2);
    for (int i = 1; i <= 3; i++)
        mm_res_scalar_i(res, O_X, i, 10 * i);
    mm_res_scalar_err(res, O_ERR, 1.5, 1e-3, MM_ERR_ESTIMATE);
    mm_series *s = mm_res_series_i(res, O_CURVE, 1, 2);
    mm_table *t = mm_res_table(res, O_T, 1);
    mm_anim *a = mm_res_animation(res, 3, "t", "s");
    mm_shape *c = a ? mm_anim_shape(res, "ball", MM_SHAPE_CIRCLE, 3, 1) : NULL;
    if (!s || !t || !c)
        return MM_ENOMEM;
    s->x[1] = s->y[1] = 1;
    t->cell[0] = 1, t->cell[1] = 0.5;
    c->radius = 0.1;
    for (int f = 0; f < 3; f++)
        a->t[f] = f, c->x[f] = f, c->y[f] = 0;
    mm_res_check_abs(res, "a", 2, 2, 0);
    return MM_OK;
}

static const mm_param no_params[] = {{"p", "a parameter", "", MM_REAL, 1, 0, 2, .help = "unused"}};
static const mm_exercise demo = {
    .id = "num-demo", .chapter = 1, .section = "1.4.1", .title = "demo", .summary = "demo",
    .theory = "none", .params = no_params, .n_params = 1, .outputs = outputs,
    .n_outputs = MM_COUNT(outputs), .solve = solve_demo,
};

static void families_should_name_every_member(void **state)
{
    (void)state;
    char buf[64];
    assert_int_equal(mm_output_count(&outputs[O_X]), 3);
    assert_int_equal(mm_output_member(&outputs[O_X], 2, buf, sizeof buf), 0);
    assert_string_equal(buf, "x2");
    assert_int_equal(mm_output_member(&outputs[O_X], 4, buf, sizeof buf), -1);
    assert_int_equal(mm_output_count(&outputs[O_CURVE]), 2);
    assert_int_equal(mm_output_index(&outputs[O_CURVE], 1), 1);
    mm_output_member(&outputs[O_CURVE], 1, buf, sizeof buf);
    assert_string_equal(buf, "y_rk4");
    assert_int_equal(mm_output_count(&outputs[O_A]), 1);
}

static void an_answer_should_carry_declared_names_accuracy_and_animation(void **state)
{
    (void)state;
    mm_buf out;
    mm_buf_init(&out, 1 << 20);
    assert_int_equal(mm_api_solve(&demo, NULL, 0, &out), 200);
    cJSON *doc = cJSON_Parse(out.p);
    assert_non_null(doc);
    const cJSON *sc = cJSON_GetObjectItem(doc, "scalars");
    assert_int_equal(cJSON_GetArraySize(sc), 5);
    const cJSON *a = cJSON_GetArrayItem(sc, 0), *x3 = cJSON_GetArrayItem(sc, 3), *e = cJSON_GetArrayItem(sc, 4);
    assert_string_equal(cJSON_GetObjectItem(a, "unit")->valuestring, "m");
    assert_true(cJSON_IsTrue(cJSON_GetObjectItem(a, "exact")));
    assert_string_equal(cJSON_GetObjectItem(x3, "name")->valuestring, "x3");
    assert_string_equal(cJSON_GetObjectItem(x3, "label")->valuestring, "component 3 of x");
    assert_null(cJSON_GetObjectItem(x3, "exact"));
    assert_string_equal(cJSON_GetObjectItem(e, "error_kind")->valuestring, "estimate");
    const cJSON *s = cJSON_GetArrayItem(cJSON_GetObjectItem(doc, "series"), 0);
    assert_string_equal(cJSON_GetObjectItem(s, "name")->valuestring, "y_rk4");
    assert_string_equal(cJSON_GetObjectItem(s, "label")->valuestring, "y by rk4");
    assert_string_equal(cJSON_GetObjectItem(s, "role")->valuestring, "reference");
    const cJSON *an = cJSON_GetObjectItem(doc, "animation");
    assert_int_equal(cJSON_GetArraySize(cJSON_GetObjectItem(an, "t")), 3);
    const cJSON *ball = cJSON_GetArrayItem(cJSON_GetObjectItem(an, "shapes"), 0);
    assert_int_equal(cJSON_GetArraySize(cJSON_GetObjectItem(ball, "x")), 3);
    check_rel(cJSON_GetObjectItem(ball, "r")->valuedouble, 0.1, 0, "circle radius");
    /* bounds from the shapes: x from -0.1 to 2.1, 5 % margin of 2.2 */
    const cJSON *bb = cJSON_GetObjectItem(an, "bounds");
    check_rel(cJSON_GetArrayItem(bb, 0)->valuedouble, -0.21, 1e-12, "xmin");
    check_rel(cJSON_GetArrayItem(bb, 2)->valuedouble, 2.21, 1e-12, "xmax");
    cJSON_Delete(doc);
    mm_buf_free(&out);
}

/* misuse and exhaustion both refuse the answer, whatever solve returns */
static int solve_wrong_kind(const mm_value *in, mm_result *res, mm_error *err)
{
    (void)in, (void)err;
    mm_res_scalar(res, O_CURVE, 1);          /* a series used as a scalar */
    mm_res_check_abs(res, "fine", 1, 1, 0);
    return MM_OK;
}

static int solve_outside_family(const mm_value *in, mm_result *res, mm_error *err)
{
    (void)in, (void)err;
    mm_scalar *s = mm_res_scalar_i(res, O_X, 7, 1);   /* x7 is not declared */
    s->exact = 1;                                      /* writes to the sink, harmlessly */
    return MM_OK;
}

static int solve_too_big(const mm_value *in, mm_result *res, mm_error *err)
{
    (void)in, (void)err;
    mm_res_alloc(res, (size_t)1 << 40);       /* over any cap */
    mm_res_check_abs(res, "would be lost", 1, 1, 0);
    return MM_OK;
}

static int solve_inner_refusal(const mm_value *in, mm_result *res, mm_error *err)
{
    (void)in, (void)res;
    return mm_error_set(err, MM_ERANGE, "t_out", "output time outside the interval");  /* a solver's own name */
}

static int solve_param_refusal(const mm_value *in, mm_result *res, mm_error *err)
{
    (void)in, (void)res;
    return mm_error_set(err, MM_ERANGE, "p", "p is too large for this model");           /* the exercise's */
}

/* A refusal from inside a solve is the request's fault only when it names
 * a parameter of the exercise: naming a solver's own argument (as
 * dyn-slider-crank's "t_out" did) it is a 500, never a 400 blaming the user. */
static void an_inner_refusal_should_not_blame_the_request(void **state)
{
    (void)state;
    mm_exercise ex = demo;
    mm_buf out;
    mm_buf_init(&out, 1 << 20);
    ex.solve = solve_inner_refusal;
    assert_int_equal(mm_api_solve(&ex, NULL, 0, &out), 500);
    assert_null(strstr(out.p, "t_out"));               /* the details go to the log */
    ex.solve = solve_param_refusal;
    assert_int_equal(mm_api_solve(&ex, NULL, 0, &out), 400);
    assert_non_null(strstr(out.p, "\"param\":\"p\""));
    mm_buf_free(&out);
}

static void failed_builders_should_refuse_the_answer(void **state)
{
    (void)state;
    mm_exercise ex = demo;
    mm_buf out;
    mm_buf_init(&out, 1 << 20);
    ex.solve = solve_wrong_kind;
    assert_int_equal(mm_api_solve(&ex, NULL, 0, &out), 500);
    ex.solve = solve_outside_family;
    assert_int_equal(mm_api_solve(&ex, NULL, 0, &out), 500);
    ex.solve = solve_too_big;
    assert_int_equal(mm_api_solve(&ex, NULL, 0, &out), 413);
    mm_buf_free(&out);
}

static void check_helpers_should_measure_against_the_reference(void **state)
{
    (void)state;
    mm_result r;
    mm_result_init(&r, 1 << 20);
    double got[3] = {1, 2.5, 3}, ref[3] = {1, 2, 4};
    /* worst |got - ref| is 1, at the last point; the tolerance is 0.3 * 4 */
    check_rel(mm_check_curve(&r, "curve", 3, got, ref, 0.3), 1, 0, "worst error");
    assert_true(r.checks.tail->tolerance == 1.2 && r.checks.tail->value == 3);
    double h[4] = {0.1, 0.05, 0.025, 0.0125}, e[4];
    for (int i = 0; i < 4; i++)
        e[i] = 3 * pow(h[i], 4);                  /* exactly fourth order */
    check_rel(mm_check_order(&r, "order", 4, h, e, 4, 0.1), 4, 1e-12, "slope of a power law");
    assert_int_equal(mm_check_residual(&r, "res", 1e-15, 10, 8), MM_OK);
    check_rel(r.checks.tail->tolerance, 8 * 2.220446049250313e-16 * 10, 1e-15, "ulps * eps * scale");
    mm_result_release(&r);
}

/* the flow check of the 1-DOF closed form passes on the true motion and
 * fails when the closed form's free part is wrong by a little: a natural
 * frequency or a damping ratio off by 1e-9, or a model whose k is 2e-9
 * stiffer than the one the closed form was built for.  (A wrong steady
 * state is not its business: the closed form is built on it, so the
 * residual of X cos(wt - phase) in eq. (1), a check of its own, finds it.) */
static void the_flow_check_should_catch_a_closed_form_off_by_1e_9(void **state)
{
    (void)state;
    mm_sdof s = {.m = 1, .c = 2, .k = 100, .F0 = 1, .omega = 8, .x0 = 0.003, .v0 = -0.2};
    mm_sdof_props p;
    mm_sdof_props_get(&s, &p);
    for (int bad = 0; bad < 4; bad++) {
        mm_result r;
        mm_result_init(&r, 1 << 20);
        mm_sdof_props q = p;
        mm_sdof t = s;
        if (bad == 1)
            q.omega_n *= 1 + 1e-9;
        if (bad == 2)
            q.zeta *= 1 + 1e-9;
        if (bad == 3)
            t.k *= 1 + 2e-9;
        assert_int_equal(mm_ex_sdof_flow_check(&t, &q, 10, &r), MM_OK);
        const mm_check_node *c = r.checks.head;
        assert_non_null(c);
        assert_int_equal(fabs(c->value - c->reference) <= c->tolerance, bad == 0);
        if (bad > 0)
            assert_true(c->value > 30 * c->tolerance);
        mm_result_release(&r);
    }
}

static void the_registry_should_be_well_formed(void **state)
{
    (void)state;
    mm_error err;
    if (mm_registry_check(&err) != MM_OK)
        fail_msg("%s", err.msg);
    assert_string_equal(mm_section_title("5.9.2"), "Undamped forced vibration");
    assert_string_equal(mm_section_title("3.8.4"), "Belt friction");
    assert_string_equal(mm_section_title("2.2.9"), "Kinematics of a particle: rectilinear and curvilinear motion");
    assert_string_equal(mm_section_title("7.1"), "");
    assert_string_equal(mm_chapter_title(3), "Statics");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(families_should_name_every_member),
        cmocka_unit_test(an_answer_should_carry_declared_names_accuracy_and_animation),
        cmocka_unit_test(failed_builders_should_refuse_the_answer),
        cmocka_unit_test(an_inner_refusal_should_not_blame_the_request),
        cmocka_unit_test(check_helpers_should_measure_against_the_reference),
        cmocka_unit_test(the_flow_check_should_catch_a_closed_form_off_by_1e_9),
        cmocka_unit_test(the_registry_should_be_well_formed),
    };
    return cmocka_run_group_tests_name("result", tests, NULL, NULL);
}
