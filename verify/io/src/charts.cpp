#include "fdh/io/charts.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace fdh::verify {
namespace {

// robust last, so that its curve (at 0) is drawn on top.
const char* const kMethods = "paper-literal paper-intended linear-system robust";

// %TERM% and %EXT% are filled in once for PNG and once for SVG.
const char* const kScript = R"GP(
set datafile separator ','
set grid

# 1. Speed against accuracy: one point per method and family.
set terminal %TERM% size 1500,520
set output 'speed_accuracy.%EXT%'
set multiplot layout 1,3 title "Speed against accuracy: one point per method and generator family (fdhcert report)"
set logscale x
set xlabel 'ns per query (log)'
set yrange [-0.02:1.02]
set key inside center right box opaque
set ylabel 'false-negative rate'
plot for [m in "exact %METHODS%"] 'data/speed_accuracy.csv' skip 1 using (strcol(1) eq m ? $4 : NaN):6 with points pt 7 ps 1.2 title m
unset key
set ylabel 'false-positive rate'
plot for [m in "exact %METHODS%"] 'data/speed_accuracy.csv' skip 1 using (strcol(1) eq m ? $4 : NaN):5 with points pt 7 ps 1.2 title m
set key inside center right box opaque
set ylabel 'error rate (FP + FN) and the Pareto front'
plot for [m in "exact %METHODS%"] 'data/speed_accuracy.csv' skip 1 using (strcol(1) eq m ? $4 : NaN):($5+$6) with points pt 7 ps 1.2 title m, \
     'data/pareto.csv' skip 1 using 3:4 with steps lw 2 lc rgb 'black' title 'Pareto front'
unset multiplot
unset logscale x

# 2. Stability: failure rate as a parameter goes to its degenerate limit.
set terminal %TERM% size 1300,900
set output 'stability.%EXT%'
set multiplot layout 2,2 title "Where methods break: share of queries wrong vs exact (0 drawn at 1e-4)"
set logscale y
set yrange [1e-4:1.5]
set ylabel 'failure rate'
set key inside left top
set xlabel 'motion-to-plane angle 2^{-p}: p'
plot for [m in "%METHODS%"] 'data/stability.csv' skip 1 using (strcol(1) eq 'angle' && strcol(3) eq m ? $2 : NaN):($4 > 1e-4 ? $4 : 1e-4) with linespoints lw 2 title m
set xlabel 'distance of the crossing from an edge 2^{-p}: p'
plot for [m in "%METHODS%"] 'data/stability.csv' skip 1 using (strcol(1) eq 'edge' && strcol(3) eq m ? $2 : NaN):($4 > 1e-4 ? $4 : 1e-4) with linespoints lw 2 title m
set xlabel 'distance from the origin 2^{p}: p'
plot for [m in "%METHODS%"] 'data/stability.csv' skip 1 using (strcol(1) eq 'magnitude' && strcol(3) eq m ? $2 : NaN):($4 > 1e-4 ? $4 : 1e-4) with linespoints lw 2 title m
set xlabel 'triangle height / base 2^{-p}: p'
plot for [m in "%METHODS%"] 'data/stability.csv' skip 1 using (strcol(1) eq 'aspect' && strcol(3) eq m ? $2 : NaN):($4 > 1e-4 ? $4 : 1e-4) with linespoints lw 2 title m
unset multiplot
unset logscale y
set autoscale y

# 3. FDH k: tree costs against the candidate pairs they produce.
set terminal %TERM% size 900,600
set output 'kdop_k.%EXT%'
set title "FDH tree, cloth over a sphere: time against candidate pairs for k = 6, 14, 18, 26\n(one group per cloth size: 30×30, 50×50, 100×100 particles; labels give k)"
set xlabel 'candidate pairs (leaf pairs reported by traversal)'
set ylabel 'ms (median of 20, log)'
set logscale y
set key inside left top
set offsets graph 0.05, graph 0.1, 0, 0
plot 'data/kdop_tree.csv' skip 1 using 8:5 with linespoints pt 7 title 'build (swept)', \
     '' skip 1 using 8:6 with linespoints pt 7 title 'refit', \
     '' skip 1 using 8:7 with linespoints pt 7 title 'traverse', \
     '' skip 1 using 8:5:(sprintf('%d', $1)) with labels offset 0,1 notitle
)GP";

std::string substitute(std::string s, const std::string& key, const std::string& value) {
  for (std::size_t p; (p = s.find(key)) != std::string::npos;) s.replace(p, key.size(), value);
  return s;
}

// Runs `script` in `dir` twice, as PNG and as SVG (%TERM% and %EXT% filled in).
void run_gnuplot(const std::string& dir, const std::string& script) {
  std::string all = "cd '" + dir + "'\n";
  for (const auto& [term, ext] :
       {std::pair<std::string, std::string>{"pngcairo", "png"}, {"svg dynamic", "svg"}})
    all += substitute(substitute(script, "%TERM%", term), "%EXT%", ext);
  std::FILE* gp = ::popen("gnuplot 2>&1", "w");
  if (!gp) throw std::runtime_error("cannot run gnuplot (Debian package gnuplot-nox)");
  std::fputs(all.c_str(), gp);
  const int status = ::pclose(gp);
  if (status != 0) throw std::runtime_error("gnuplot failed (is Debian's gnuplot-nox installed?)");
}

}  // namespace

void draw_charts(const std::string& dir) {
  run_gnuplot(dir, substitute(kScript, "%METHODS%", kMethods));
}

namespace {

const char* const kTable1Script = R"GP(
set datafile separator ','
set grid
set terminal %TERM% size 900,600
set output 'table1.%EXT%'
set title "Table 1: ms per frame, cloth on a table (fdhcert table1)\nthe paper's rows on a 2.8 GHz Pentium IV; ours on this machine"
set xlabel 'particles'
set ylabel 'ms per frame (log)'
set logscale y
set key outside right top
series = "linear-system~k=18 paper-intended~k=18 robust~k=6 robust~k=14 robust~k=18 robust~k=26 paper:~traditional paper:~this~paper"
name(s) = system(sprintf("echo '%s' | tr '~' ' '", s))
plot for [s in series] 'data/table1.csv' skip 1 using (strcol(1) eq name(s) ? $4 : NaN):5 with linespoints lw 2 pt 7 title name(s)
)GP";

}  // namespace

void draw_table1_chart(const std::string& dir) {
  run_gnuplot(dir, kTable1Script);
}

}  // namespace fdh::verify
