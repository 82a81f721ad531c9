/* replay.c — runs a fuzz target's committed corpus (tests/fuzz/corpus/NAME/)
 * once, as a regression test in `make test`: every input that once crashed
 * stays in the corpus, so the crash cannot come back unnoticed. */
#include "mm_test.h"

#include <dirent.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv) __attribute__((weak));

#ifndef FUZZ_NAME
#error FUZZ_NAME must name the corpus folder
#endif

static void the_committed_corpus_should_run_clean(void **state)
{
    (void)state;
    if (LLVMFuzzerInitialize)
        LLVMFuzzerInitialize(NULL, NULL);
    const char *dirname = "tests/fuzz/corpus/" FUZZ_NAME;
    DIR *d = opendir(dirname);
    assert_non_null(d);
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.')
            continue;
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", dirname, e->d_name);
        FILE *f = fopen(path, "rb");
        assert_non_null(f);
        static unsigned char buf[1 << 20];
        size_t len = fread(buf, 1, sizeof buf, f);
        fclose(f);
        LLVMFuzzerTestOneInput(buf, len);   /* aborts on a broken invariant */
        n++;
    }
    closedir(d);
    print_message("%d inputs from %s\n", n, dirname);
    assert_true(n > 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_committed_corpus_should_run_clean),
    };
    return cmocka_run_group_tests_name("fuzz corpus " FUZZ_NAME, tests, NULL, NULL);
}
