// Exercise NN over the judge's wire (../harness/judge_wire.hpp), part of the grader, not of
// your solution. Compiled with T2_JUDGE_CHECKER it stands in for your functions inside the
// tests (each call goes to the sandboxed driver that runs your code); compiled without, it is the
// driver's table of your functions.
#include "api.hpp"

#include "judge_wire.hpp"

#ifdef T2_JUDGE_CHECKER
namespace exNN {
bool example(const t2::Point& p) { return t2judge::call<bool>("example", p); }
}  // namespace exNN
#else
const std::map<std::string, t2judge::Handler>& t2judge::table() {
  static const std::map<std::string, Handler> t = {
      {"example", handler(&exNN::example)},
  };
  return t;
}
#endif
