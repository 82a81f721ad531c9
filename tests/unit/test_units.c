/* test_units.c — a learner's number with its unit, read into SI. */
#include "mm_test.h"

#include <string.h>

#include "mm_units.h"

static mm_quantity q(const char *text)
{
    mm_quantity r;
    mm_error err;
    if (mm_quantity_parse(text, &r, &err) != MM_OK)
        fail_msg("'%s': %s", text, err.msg);
    return r;
}

static void dims(const mm_quantity *x, const char *want)
{
    char buf[64];
    mm_dim_text(x, buf, sizeof buf);
    assert_string_equal(buf, want);
}

static void prefixes_and_derived_units_should_convert_to_si(void **state)
{
    (void)state;
    mm_quantity a = q("256.6 N"), b = q("0.2566 kN"), c = q("25 mm"), d = q("1,5 kN");
    check_rel(a.value, 256.6, 0, "N");
    check_rel(b.value, 256.6, 1e-15, "kN is 1000 N");
    assert_true(mm_dim_equal(&a, &b));
    dims(&a, "kg m s^-2");
    check_rel(c.value, 0.025, 1e-15, "mm");
    dims(&c, "m");
    check_rel(d.value, 1500, 0, "a decimal comma");
    check_rel(q("3 kg").value, 3, 0, "kg is the base unit, factor exactly 1");
    check_rel(q("2 t").value, 2000, 0, "tonne");
    check_rel(q("1.2 MPa").value, 1.2e6, 1e-15, "MPa");
    check_rel(q("9.81 m/s^2").value, 9.81, 0, "acceleration");
    mm_quantity acc = q("9.81 m/s^2");
    dims(&acc, "m s^-2");
    mm_quantity ns = q("20 N s/m");
    dims(&ns, "kg s^-1");
    mm_quantity nm = q("4.2 kN*m"), nm2 = q("4.2 kNm"), nm3 = q("4200 N\xc2\xb7m");
    check_rel(nm.value, 4200, 1e-15, "kN*m");
    check_rel(nm2.value, 4200, 1e-15, "kNm");
    assert_true(mm_dim_equal(&nm, &nm2) && mm_dim_equal(&nm, &nm3));
    mm_quantity area = q("3 cm\xc2\xb2"), inertia = q("8 cm^4");
    check_rel(area.value, 3e-4, 1e-15, "cm squared");
    check_rel(inertia.value, 8e-8, 1e-15, "cm^4");
    dims(&inertia, "m^4");
    check_rel(q("-1.5e3").value, -1500, 0, "a bare number");
    assert_false(q("-1.5e3").has_unit);
    check_rel(q("5 %").value, 0.05, 1e-15, "percent");
}

static void angles_and_rates_should_convert_but_not_mix_with_hertz(void **state)
{
    (void)state;
    mm_quantity deg = q("90 deg"), deg2 = q("90\xc2\xb0"), rad = q("1.5707963267948966 rad");
    check_rel(deg.value, M_PI / 2, 1e-15, "degrees");
    check_rel(deg2.value, M_PI / 2, 1e-15, "the degree sign");
    assert_true(mm_dim_equal(&deg, &rad));
    mm_quantity rpm = q("3000 rpm"), w = q("314.159 rad/s"), hz = q("50 Hz");
    check_rel(rpm.value, 100 * M_PI, 1e-15, "3000 rpm = 100 pi rad/s");
    assert_true(mm_dim_equal(&rpm, &w));
    assert_false(mm_dim_equal(&w, &hz));     /* cycles per second are not radians per second */
    dims(&hz, "s^-1");
    mm_quantity per = q("0.5 1/s"), per_ms = q("2 1/ms");
    check_rel(per.value, 0.5, 1e-15, "1/s: a numerator of one");
    check_rel(per_ms.value, 2000, 1e-15, "1/ms");
    assert_true(mm_dim_equal(&per, &hz));
}

static void unknown_units_and_bad_numbers_should_be_refused(void **state)
{
    (void)state;
    mm_quantity r;
    mm_error err;
    assert_int_equal(mm_quantity_parse("12 furlongs", &r, &err), MM_EVALUE);
    assert_non_null(strstr(err.msg, "furlongs"));
    assert_int_equal(mm_quantity_parse("N 12", &r, &err), MM_EVALUE);
    assert_int_equal(mm_quantity_parse("", &r, &err), MM_EVALUE);
    assert_int_equal(mm_quantity_parse("1e999 N", &r, &err), MM_EVALUE);
    assert_int_equal(mm_quantity_parse("2 m/s/s", &r, &err), MM_EVALUE);
    assert_int_equal(mm_quantity_parse("2 m^x", &r, &err), MM_EVALUE);
    assert_int_equal(mm_quantity_parse("2 kdeg", &r, &err), MM_EVALUE);   /* deg takes no prefix */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(prefixes_and_derived_units_should_convert_to_si),
        cmocka_unit_test(angles_and_rates_should_convert_but_not_mix_with_hertz),
        cmocka_unit_test(unknown_units_and_bad_numbers_should_be_refused),
    };
    return cmocka_run_group_tests_name("units", tests, NULL, NULL);
}
