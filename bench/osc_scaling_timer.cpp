// rbdc-osc-scaling-timer ROBOT.urdf: mean time per call (ns) of the runtime's generic closed-chain
// recursion (paper 001 Table 2) and of the runtime's closed form (Eqs. 16-26), every foot in
// contact, over cycled random states (process CPU time). tools/scaling_study.py uses it for the
// timing companion of paper 001 Fig. 8; prints one JSON object.
#include <cmath>
#include <ctime>
#include <cstdio>
#include <exception>
#include <numeric>
#include <random>
#include <vector>

#include "rbdc/osc.hpp"
#include "rbdc/sim/robot.hpp"

using namespace rbdc;

namespace {

template <class Call>
double mean_ns(int calls, Call&& call) {
  for (int i = 0; i < calls / 10 + 1; ++i) call(i);  // warm-up
  // Process CPU time, not wall time: the figure should not depend on other jobs on the machine.
  const std::clock_t start = std::clock();
  for (int i = 0; i < calls; ++i) call(i);
  return 1e9 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC / calls;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fputs("usage: rbdc-osc-scaling-timer ROBOT.urdf\n", stderr);
    return 2;
  }
  try {
    const Model model = sim::load_robot(argv[1]);
    Data data(model);
    OscReferenceData reference(model);
    std::vector<int> feet(model.feet.size());
    std::iota(feet.begin(), feet.end(), 0);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> angle(-0.5, 0.5);
    std::vector<VectorX> qs, vs;
    for (int s = 0; s < 16; ++s) {
      VectorX q = VectorX::Zero(model.nq), v = VectorX::Zero(model.nv);
      q[3] = 1;
      for (int i = 7; i < model.nq; ++i) q[i] = angle(rng);
      for (int i = 0; i < model.nv; ++i) v[i] = angle(rng);
      qs.push_back(q), vs.push_back(v);
    }
    double sink = 0;
    const double recursion = mean_ns(10000, [&](int i) {
      sink += osc_closed_chain(model, data, qs[i % 16], vs[i % 16], feet).b[0];
    });
    const double closed_form = mean_ns(2000, [&](int i) {
      sink += osc_closed_form_constrained(model, data, reference, qs[i % 16], vs[i % 16], feet).b[0];
    });
    // Printing whether the outputs were finite uses them, so no call can be optimised away.
    std::printf("{\"runtime_recursion_ns\": %.1f, \"runtime_closed_form_ns\": %.1f, \"nv\": %d, "
                "\"finite\": %s}\n",
                recursion, closed_form, model.nv, std::isfinite(sink) ? "true" : "false");
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rbdc-osc-scaling-timer: %s\n", e.what());
    return 1;
  }
}
