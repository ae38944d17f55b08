/* layout_test.c: cl_layout_valid() accepts a header laid out from its sizes and refuses every
   header whose sizes, offsets or total size disagree (the loader checks shared memory with it). */
#include <stdio.h>
#include "cl_data.h"

/* Print one case: what was changed and whether the header is still accepted. */
static void show(const char *what, const cl_header_t *h)
{
    printf("%-28s %s\n", what, cl_layout_valid(h) ? "accepted" : "refused");
}

int main(void)
{
    int32_t sizes[CL_N_SIZES];
    cl_header_t good, h;

    for (int i = 0; i < CL_N_SIZES; i++)
        sizes[i] = 10 + i;
    cl_layout(&good, sizes);
    show("as laid out", &good);
    h = good; h.offsets[3] += 16;
    show("one offset moved", &h);
    h = good; h.total_size -= 16;
    show("total size too small", &h);
    h = good; h.sizes[0] += 1;
    show("a size grown", &h);
    h = good; h.sizes[1] = -1;
    show("a negative size", &h);
    h = good; h.sizes[2] = CL_MAX_ARRAY_SIZE + 1;
    show("a size beyond the maximum", &h);
    sizes[0] = 0;
    cl_layout(&h, sizes);
    show("an empty array", &h);
    return 0;
}
