// cgal-delaunay: a bare CGAL 2D Delaunay triangulation of a point file, for sigdt's speed
// comparison only (`make bench`, crates/sigdt/examples/speed.rs). Not part of any shipped
// crate; links CGAL (GPL-3), see LICENSE.md beside this file.
//
// Usage: cgal-delaunay FILE [--reps R]
//   FILE: one point per line, "x y" (whitespace-separated; other lines are skipped).
// Prints one line: "n=N vertices=V faces=F ms=M" where M is the median wall time over R runs
// (default 1) of building the triangulation from the points in memory: CGAL's range insert,
// which sorts the points spatially (Hilbert, BRIO) and inserts them with a walk, exact
// predicates (Epick: filtered, exact on failure). Reading the file is not timed.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Dt = CGAL::Delaunay_triangulation_2<K>;
using P = K::Point_2;

static std::vector<P> read_points(const char* path) {
    std::FILE* f = std::fopen(path, "r");
    if (!f) {
        std::perror(path);
        std::exit(1);
    }
    std::vector<P> points;
    char line[4096];
    while (std::fgets(line, sizeof line, f)) {
        char* end = nullptr;
        double x = std::strtod(line, &end);
        if (end == line) continue;
        char* end2 = nullptr;
        double y = std::strtod(end, &end2);
        if (end2 == end) continue;
        points.emplace_back(x, y);
    }
    std::fclose(f);
    return points;
}

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: cgal-delaunay FILE [--reps R]\n");
        return 2;
    }
    int reps = 1;
    for (int i = 2; i + 1 < argc; i += 2) {
        if (std::strcmp(argv[i], "--reps") == 0) reps = std::max(1, std::atoi(argv[i + 1]));
    }
    std::vector<P> points = read_points(argv[1]);
    std::vector<double> ms;
    std::size_t vertices = 0, faces = 0;
    for (int r = 0; r < reps; ++r) {
        auto start = std::chrono::steady_clock::now();
        Dt dt;
        dt.insert(points.begin(), points.end());
        auto stop = std::chrono::steady_clock::now();
        ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
        vertices = dt.number_of_vertices();
        faces = dt.number_of_faces();
    }
    std::sort(ms.begin(), ms.end());
    std::size_t m = ms.size();
    double median = m % 2 ? ms[m / 2] : 0.5 * (ms[m / 2 - 1] + ms[m / 2]);
    std::printf("n=%zu vertices=%zu faces=%zu ms=%.3f\n", points.size(), vertices, faces, median);
    return 0;
}
