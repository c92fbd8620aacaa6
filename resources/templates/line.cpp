// A line algorithm of your own in C++, for RasterLab to check.
//
//     c++ -O2 -std=c++17 -o raster line.cpp
//     rasterlab check --cmd ./raster raster --against line-bresenham
//
// RasterLab runs the program once per case. It reads the case as one JSON
// line on stdin, {"against": "line-bresenham", "args": [x0, y0, x1, y1]},
// with whole end points (y up), and writes one JSON line per pixel on
// stdout, from (x0, y0) to (x1, y1), then {"done": true}:
//
//     {"x": 0, "y": 0, "vars": {"d": -1}}
//
// A variable is compared when it has the reference's name: Bresenham's
// decision variable is "d", the value tested before it is updated (the
// first pixel shows the starting d = 2*dy - dx); ties (d = 0) step along
// the major axis only. Messages of your own go to std::cerr, never std::cout.
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

// One pixel and its decision variable, as a line of JSON.
static void step(long x, long y, long d)
{
    std::cout << "{\"x\": " << x << ", \"y\": " << y << ", \"vars\": {\"d\": " << d << "}}\n";
}

// ---- your algorithm: from here ----
static void draw(long x0, long y0, long x1, long y1)
{
    // TODO: replace with your algorithm. This draws only the two ends.
    step(x0, y0, 0);
    if (x1 != x0 || y1 != y0)
        step(x1, y1, 0);
}
// ---- to here ----

// The numbers of "args" in the case's line, in order.
static std::vector<double> read_args(const std::string &line)
{
    std::vector<double> args;
    std::size_t at = line.find("\"args\"");
    if (at == std::string::npos)
        return args;
    const char *p = line.c_str() + line.find('[', at);
    while (*p != '\0') {
        char *end;
        double value = std::strtod(p, &end);
        if (end == p)
            ++p;
        else {
            args.push_back(value);
            p = end;
        }
    }
    return args;
}

int main()
{
    std::string line;
    std::getline(std::cin, line);
    std::vector<double> a = read_args(line);
    if (a.size() != 4) {
        std::cout << "{\"error\": \"expected a case line with four args\"}\n";
        return 1;
    }
    draw(long(a[0]), long(a[1]), long(a[2]), long(a[3]));
    std::cout << "{\"done\": true}" << std::endl;
    return 0;
}
