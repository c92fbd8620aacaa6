// A line algorithm of your own in JavaScript, for RasterLab to check.
//
//     rasterlab check --cmd "node {}" line.js --against line-bresenham
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
// the major axis only. Messages of your own go to console.error, never
// console.log. Plain node only: no packages.
"use strict";

const lines = [];

// One pixel and its named variables, as a line of JSON.
function step(x, y, vars = {}) {
    lines.push(JSON.stringify({ x, y, vars }));
}

// ---- your algorithm: from here ----
function draw(x0, y0, x1, y1) {
    // TODO: replace with your algorithm. This draws only the two ends.
    step(x0, y0);
    if (x1 !== x0 || y1 !== y0) step(x1, y1);
}
// ---- to here ----

const request = JSON.parse(require("fs").readFileSync(0, "utf8"));
draw(...request.args);
lines.push(JSON.stringify({ done: true }));
process.stdout.write(lines.join("\n") + "\n");
