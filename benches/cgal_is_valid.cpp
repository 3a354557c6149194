// Peer measurement for BENCHMARKS.md: CGAL's Triangulation_3::is_valid on the Delaunay
// tetrahedralization of the points of a TetGen .node file. Prints the build time and the
// median is_valid time over R runs (default 3). Build: see benches/run.sh.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Delaunay_triangulation_3<K> DT;

static double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

int main(int argc, char** argv) {
    if (argc < 2) { std::cerr << "usage: cgal_is_valid points.node [runs]\n"; return 2; }
    int runs = argc > 2 ? std::atoi(argv[2]) : 3;
    std::ifstream in(argv[1]);
    std::string line;
    std::vector<K::Point_3> pts;
    bool header = true;
    while (std::getline(in, line)) {
        auto h = line.find('#');
        if (h != std::string::npos) line = line.substr(0, h);
        std::istringstream ss(line);
        if (header) { long n; if (ss >> n) { header = false; pts.reserve(n); } continue; }
        long idx; double x, y, z;
        if (ss >> idx >> x >> y >> z) pts.emplace_back(x, y, z);
    }
    double t0 = now();
    DT dt(pts.begin(), pts.end());
    double build = now() - t0;
    std::vector<double> times;
    bool ok = true;
    for (int r = 0; r < runs; r++) {
        double t = now();
        ok = ok && dt.is_valid();
        times.push_back(now() - t);
    }
    std::sort(times.begin(), times.end());
    std::printf("{\"points\":%zu,\"cells\":%zu,\"build_seconds\":%.4f,\"is_valid_seconds\":%.4f,\"valid\":%s}\n",
                pts.size(), (size_t)dt.number_of_finite_cells(), build, times[times.size() / 2], ok ? "true" : "false");
    return 0;
}
