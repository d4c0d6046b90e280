// Google Benchmark's console reporter, also keeping each benchmark's median time (or its single
// run's time) so that a program can print ratios measured side by side in one run.
#ifndef PhongVTKMedianReporter_h
#define PhongVTKMedianReporter_h

#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

namespace phongvtk
{
namespace benchmarks
{

class MedianReporter : public benchmark::ConsoleReporter
{
public:
  /// Seconds per iteration by benchmark name (without the argument suffixes).
  std::map<std::string, double> Seconds;
  void ReportRuns(const std::vector<Run>& runs) override
  {
    benchmark::ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs)
    {
      const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
      const bool single = run.run_type == Run::RT_Iteration && run.repetitions <= 1;
      if (median || single)
      {
        this->Seconds[run.run_name.function_name] =
          run.real_accumulated_time / static_cast<double>(run.iterations);
      }
    }
  }
};

}
}

#endif
