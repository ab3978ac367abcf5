// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL's Optimal_transportation_reconstruction_2 on one point set, for comparison with
// sigdt's OPTIMALTRANSPORT. GPL-3.0-or-later, because it links CGAL (see README.md).
//
//   otr (--until N | --steps S | --tolerance T) [--relocation R] < points.xy > out.segments
//
// Reads `x y` lines, runs the reconstruction with CGAL's defaults (exhaustive queue, flips,
// 2 relocations, relevance 1) and the given stopping rule, writes each output segment as
// `x0 y0 x1 y1` (17 significant digits) and a summary line on stderr.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Optimal_transportation_reconstruction_2.h>

#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef K::Segment_2 Segment;
typedef CGAL::Optimal_transportation_reconstruction_2<K> Otr;

static int usage() {
  std::cerr << "usage: otr (--until N | --steps S | --tolerance T) [--relocation R]"
               " < points.xy > out.segments\n";
  return 2;
}

int main(int argc, char** argv) {
  std::string rule;
  double value = -1.0;
  int relocation = -1;
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string flag = argv[i];
    if (flag == "--relocation") relocation = std::atoi(argv[i + 1]);
    else if (flag == "--until" || flag == "--steps" || flag == "--tolerance") {
      rule = flag;
      value = std::atof(argv[i + 1]);
    } else return usage();
  }
  if (rule.empty() || value < 0.0 || argc % 2 == 0) return usage();
  std::vector<Point> points;
  double x, y;
  while (std::cin >> x >> y) points.push_back(Point(x, y));
  Otr otr(points);
  if (relocation >= 0) otr.set_relocation(static_cast<unsigned int>(relocation));
  if (rule == "--until") otr.run_until(static_cast<std::size_t>(value));
  else if (rule == "--steps") otr.run(static_cast<unsigned int>(value));
  else otr.run_under_wasserstein_tolerance(value);
  std::vector<Point> isolated;
  std::vector<Segment> segments;
  otr.list_output(std::back_inserter(isolated), std::back_inserter(segments));
  std::cout << std::setprecision(17);
  for (const Segment& s : segments)
    std::cout << s.source().x() << ' ' << s.source().y() << ' ' << s.target().x() << ' '
              << s.target().y() << '\n';
  std::cerr << points.size() << " points, " << otr.number_of_vertices() << " vertices, "
            << segments.size() << " segments, " << isolated.size() << " isolated\n";
  return 0;
}
