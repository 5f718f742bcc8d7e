/* Stands in for the Box2D cross-check when CMake found no Box2D: reports the test skipped
 * (exit code 77, ctest's SKIP_RETURN_CODE) instead of passing silently. */
#include <stdio.h>

int main(void)
{
    puts("test_box2d_toi: SKIPPED: Box2D 3.1 not found (pip install pyb2d3==0.11.1 and add its "
         "root to CMAKE_PREFIX_PATH; see DEVELOPERS.md)");
    return 77;
}
