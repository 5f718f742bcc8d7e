/* The speed colour map: piecewise linear through five hand-picked stops, chosen so that resting
 * bodies are a calm blue, typical ones green and the fastest a hot red. No pow or exp: the same
 * speed gives the same colour on every platform. */
#include "colour.h"

static const float stops[5][3] = {
    {38.0f, 64.0f, 190.0f},  /* 0.00: at rest */
    {40.0f, 165.0f, 225.0f}, /* 0.25 */
    {80.0f, 205.0f, 110.0f}, /* 0.50 */
    {245.0f, 200.0f, 50.0f}, /* 0.75 */
    {235.0f, 60.0f, 40.0f},  /* 1.00: reference speed and above */
};

demo_rgb demo_speed_colour(double s)
{
    int k;
    float f;
    if (!(s > 0.0))
        s = 0.0;
    if (s > 1.0)
        s = 1.0;
    k = (int)(s * 4.0);
    if (k > 3)
        k = 3;
    f = (float)(s * 4.0 - k);
    return demo_rgb_make(stops[k][0] + (stops[k + 1][0] - stops[k][0]) * f,
                         stops[k][1] + (stops[k + 1][1] - stops[k][1]) * f,
                         stops[k][2] + (stops[k + 1][2] - stops[k][2]) * f);
}
