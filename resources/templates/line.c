/* A line algorithm of your own in C, for RasterLab to check.

    cc -O2 -o raster line.c
    rasterlab check --cmd ./raster raster --against line-bresenham

RasterLab runs the program once per case. It reads the case as one JSON
line on stdin, {"against": "line-bresenham", "args": [x0, y0, x1, y1]},
with whole end points (y up), and writes one JSON line per pixel on
stdout, from (x0, y0) to (x1, y1), then {"done": true}:

    {"x": 0, "y": 0, "vars": {"d": -1}}

A variable is compared when it has the reference's name: Bresenham's
decision variable is "d", the value tested before it is updated (the
first pixel shows the starting d = 2*dy - dx); ties (d = 0) step along the
major axis only. Messages of your own go to stderr, never stdout.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One pixel and its decision variable, as a line of JSON. */
static void step(long x, long y, long d)
{
    printf("{\"x\": %ld, \"y\": %ld, \"vars\": {\"d\": %ld}}\n", x, y, d);
}

/* ---- your algorithm: from here ---- */
static void draw(long x0, long y0, long x1, long y1)
{
    /* TODO: replace with your algorithm. This draws only the two ends. */
    step(x0, y0, 0);
    if (x1 != x0 || y1 != y0)
        step(x1, y1, 0);
}
/* ---- to here ---- */

/* The numbers of "args" in the case's line, in order. */
static int read_args(const char *line, double *args, int most)
{
    const char *p = strstr(line, "\"args\"");
    int n = 0;
    if (p == NULL)
        return 0;
    p = strchr(p, '[');
    while (p != NULL && *p != '\0' && n < most) {
        char *end;
        double value = strtod(p, &end);
        if (end == p)
            p++;
        else {
            args[n++] = value;
            p = end;
        }
    }
    return n;
}

int main(void)
{
    static char line[1 << 16];
    double a[4];
    if (fgets(line, sizeof line, stdin) == NULL || read_args(line, a, 4) != 4) {
        printf("{\"error\": \"expected a case line with four args\"}\n");
        return 1;
    }
    draw((long)a[0], (long)a[1], (long)a[2], (long)a[3]);
    printf("{\"done\": true}\n");
    return 0;
}
