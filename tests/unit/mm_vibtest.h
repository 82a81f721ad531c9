/* mm_vibtest.h — the vib tests' name for mm_answer.h (the answer readers
 * every chapter's tests share). */
#ifndef MM_VIBTEST_H
#define MM_VIBTEST_H

#include "mm_answer.h"

#endif
