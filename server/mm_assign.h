/* mm_assign.h — assignments: a variant of an exercise per student, drawn
 * from a seed, and answers judged with tolerances and units (API.md
 * "assignments"; the course file holds them, mm_course.h).
 *
 * An assignment in the course file:
 *
 *   {"name": "belt-1", "title": "Belt friction around a bollard",
 *    "exercise": "sta-belt-friction",
 *    "params": {"T1": {"min": 50, "max": 500, "step": 10},      a range with a step
 *               "mu": {"values": [0.2, 0.25, 0.3]},            a list (names for a choice)
 *               "theta": {"min": 1, "max": 4, "sig": 2},        every number with 2
 *               "g": 9.81},                                     significant figures; fixed
 *    "ask": [{"name": "T2", "unit": "kN", "rel": 0.01},        relative tolerance
 *            {"name": "T2", "sig": 3},                          significant figures
 *            {"name": "phase", "unit": "deg", "abs": 0.5}],    absolute, in the asked unit
 *    "class_size": 300,                     expected class (for the duplicate warning)
 *    "students": ["s001", "s002"],          optional roster: distinct variants, in order
 *    "reveal": true,                        expected answers shown by a check (default)
 *    "instructor_key": "s3cret"}            unlocks the answer key and the class CSV
 *
 * The judging rules, as the instructor reads them:
 *   - An answer is a number with a unit ("256.6 N", "0.2566 kN", "1,5 kN");
 *     it is converted to the asked unit (the output's SI unit unless the
 *     assignment names another of the same dimension).  A number without a
 *     unit where the answer has one, or a unit of another dimension, is an
 *     error of the answer (reported, never judged silently).  A
 *     dimensionless answer takes a bare number (or %).
 *   - Tolerance: right when |given - expected| <= max(abs, rel |expected|),
 *     both in the asked unit; the edge counts as right (with 1e-12 relative
 *     slack for the decimal conversion).  Against an expected answer of
 *     exactly 0 a relative tolerance allows 0 only: give "abs" for answers
 *     that can be zero (the check says so when it happens).
 *   - Significant figures: right when the given value rounds to the same n
 *     significant figures as the exact answer, both in the asked unit,
 *     rounding half away from zero (1.0000 and 1 agree at 3: both are 1.00;
 *     the given value is rounded from the digits typed, so 1.005 is 1.01).
 *     An exact answer of 0 has no significant figures: only 0 is right.
 *   - score = the number of asked answers judged right.
 *
 * Variants: the parameters of student S are a pure function of (the
 * assignment's name, S): a 64-bit FNV-1a hash of both seeds a generator,
 * each varying parameter is drawn uniformly from its set, and a draw that
 * the exercise's limits or joint check refuse is never handed out (the
 * next draw of the same stream is taken).  With a roster, students are
 * placed in its order and each takes the first draw of its stream that no
 * earlier student holds, so variants are distinct while the set allows and
 * adding students at the end never changes a variant handed out.  Without
 * a roster, two students share a variant with the birthday probability
 * (the notes at load give it for class_size).
 */
#ifndef MM_ASSIGN_H
#define MM_ASSIGN_H

#include <cJSON.h>

#include "mm_api.h"
#include "mm_exercise.h"
#include "mm_json.h"
#include "mm_units.h"

#define MM_ASSIGN_MAX_ASK 16
#define MM_ASSIGN_MAX_LIST 10000
#define MM_ASSIGN_MAX_STUDENTS 5000

typedef struct mm_assignment mm_assignment;

/* The exercise id an assignment object names, or NULL. */
const char *mm_assign_exercise_id(const cJSON *j);

/* Read and check assignment j against its exercise ex (the course's, with
 * its limits).  notes receives what the instructor should know ("50
 * variants for a class of 300: duplicates are unavoidable").  Returns
 * MM_OK with *out, or MM_EVALUE with err saying what is wrong (the param
 * field names the key). */
int mm_assign_load(const cJSON *j, const mm_exercise *ex, mm_assignment **out, mm_buf *notes,
                   mm_error *err);
void mm_assign_free(mm_assignment *a);

const char *mm_assign_name(const mm_assignment *a);
const char *mm_assign_title(const mm_assignment *a);
const mm_exercise *mm_assign_exercise(const mm_assignment *a);
/* the number of distinct parameter sets the assignment can hand out
 * (before joint limits), as a double: it may be huge */
double mm_assign_set_size(const mm_assignment *a);

/* The inputs of student's variant (every parameter of the exercise, as
 * text) into in[] and text[] (MM_MAX_PARAMS entries of MM_ASSIGN_TEXT
 * bytes); *n the count.  Returns MM_OK, or MM_EVALUE for an empty student
 * id or one over 128 bytes, MM_ENOCONV when no draw in 1000 passes the
 * exercise's limits. */
#define MM_ASSIGN_TEXT 4096
int mm_assign_variant(const mm_assignment *a, const char *student, mm_input *in,
                      char (*text)[MM_ASSIGN_TEXT], int *n, mm_error *err);

/* GET .../variant?student=S: {"assignment","student","exercise","title",
 * "params":{...},"asked":[{"name","label","unit","rule"}]}.  Returns the
 * HTTP status (400 for a bad student id). */
int mm_assign_variant_json(const mm_assignment *a, const char *student, mm_buf *out);

/* POST .../check with body {"student":S,"answers":{"T2":"256.6 N",...}}:
 * {"assignment","student","results":[{"name","correct","given","expected",
 * "unit","tolerance","rule","error"?,"note"?}],"score":k,"max_score":n}.
 * Returns the HTTP status. */
int mm_assign_check_json(const mm_assignment *a, const char *body, size_t len, mm_buf *out);

/* The instructor's key of the assignment ("instructor_key" in the course
 * file), or NULL when it has none (then the instructor's routes are off). */
const char *mm_assign_key(const mm_assignment *a);

/* For the instructor: from a class list (CSV text, the student id in the
 * first column, an optional header line "id,..." skipped, at most
 * MM_ASSIGN_MAX_STUDENTS lines), a CSV with one row per student: the id,
 * every parameter of the variant, and every asked answer in its asked unit
 * (17 significant digits).  Returns the HTTP status (400 for a bad list). */
int mm_assign_csv(const mm_assignment *a, const char *list, size_t len, mm_buf *out);

/* For the instructor: the variant with its expected answers and the whole
 * solve answer ({"variant":{...},"expected":[{"name","value","unit"}],
 * "answer":{...}}).  Returns the HTTP status. */
int mm_assign_key_json(const mm_assignment *a, const char *student, mm_buf *out);

/* One judgement, for tests and for the instructor's sheets. */
typedef struct mm_judgement {
    int correct;
    double given, expected;    /* in the asked unit */
    double tolerance;          /* absolute, in the asked unit (sig: half the last place) */
    char error[256];           /* "" or why the answer could not be judged */
    char note[160];            /* "" or a remark (a zero answer under a relative tolerance) */
} mm_judgement;

typedef struct mm_rule {
    double rel, abs;           /* tolerances (abs in the asked unit) */
    int sig;                   /* > 0: significant figures instead */
    char unit[32];             /* the asked unit ("" dimensionless) */
} mm_rule;

/* Judge the answer text against expected_si (the value in SI units of
 * dimension `dim`) under rule.  Cannot fail: a bad answer sets error. */
void mm_assign_judge(const mm_rule *rule, const mm_quantity *dim, double expected_si,
                     const char *given, mm_judgement *j);

#endif
