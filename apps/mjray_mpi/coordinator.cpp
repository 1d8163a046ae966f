#include "coordinator.h"

#include <cstdio>

#include "frame_phase.h"
#include "job_images.h"
#include "messages.h"
#include "rank_failed.h"
#include "tile_distributor.h"
#include "mjray/job/job_outputs.h"
#include "mjray/job/prepared_job.h"
#include "mjray/render/tile_render.h"

namespace mjray {

namespace {

/// Each other rank's report of a tile job, by rank (Ready messages of ranks that came too late
/// to render are passed over). Throws RankFailed.
std::vector<RankStatistics> collect_reports(MpiWorld& world) {
  std::vector<RankStatistics> reports;
  while (int(reports.size()) + 1 < world.size()) {
    const auto message = world.wait(1.0);
    if (!message) continue;
    const MessageType type = type_of(message->bytes);
    if (type == MessageType::kFailed) throw RankFailed(message->from, decode_failed(message->bytes).text);
    if (type == MessageType::kJobReport) reports.push_back(decode_job_report(message->bytes));
  }
  std::sort(reports.begin(), reports.end(), [](const auto& a, const auto& b) { return a.rank < b.rank; });
  return reports;
}

/// One job whose tiles every rank shares: rank 0 plans each pass and writes the image.
JobStatistics render_tile_job(MpiWorld& world, const RunSetup& setup, size_t index, const ResumePlan& plan) {
  const uint64_t bytes_before = world.bytes_sent();
  for (int k = 1; k < world.size(); ++k)
    world.send(k, encode(TileJobMessage{uint32_t(index), int32_t(std::max(1, setup.options.render.tile_size))}));

  // Compute the job here while the others compute theirs; then its image on every rank.
  const PreparedJob job(setup.scene, index, setup.options);
  print_warnings(job.warnings());
  JobStatistics stats = prepared_job_statistics(job, setup.ranks[0].seconds_load);
  RankStatistics local;
  const int threads = resolve_thread_count(setup.options.render.threads);
  render_prepared_job(job, plan.state, setup.options, setup.plan.fingerprints.of(index), setup.run, stats,
                      [&](const ImageSampler& sampler, const TileLayout& layout) {
                        return std::make_unique<TileDistributor>(world, sampler, layout, threads, local);
                      });

  // Compute what each rank did.
  for (int k = 1; k < world.size(); ++k) world.send(k, encode(MessageType::kEndJob));
  local.rank = 0;
  local.host = setup.ranks[0].host;
  local.seconds_load = setup.ranks[0].seconds_load;
  local.seconds_build = job.build_seconds();
  local.bytes_sent = world.bytes_sent() - bytes_before;
  stats.ranks = {local};
  for (const RankStatistics& report : collect_reports(world)) stats.ranks.push_back(report);
  return stats;
}

}  // namespace

void run_coordinator(MpiWorld& world, const RunSetup& setup) {
  // Decide what --resume keeps, before building anything.
  std::vector<ResumePlan> plans(setup.scene.jobs.size());
  std::vector<size_t> jobs;
  for (const size_t i : setup.plan.jobs) {
    const auto image = output_path(setup.scene, i, setup.options.outputs);
    plans[i] = plan_resume(image, setup.plan.fingerprints.of(i), setup.run.resume);
    if (!plans[i].keep) jobs.push_back(i);
    else if (!setup.run.quiet) std::fprintf(stderr, "mjray: kept %s (complete)\n", image.string().c_str());
  }

  // Compute the images: whole frames first, then the jobs whose tiles all ranks share.
  const JobSplit split = split_jobs(jobs, world.size(), setup.distribution);
  StatisticsLog log(setup.stats_json);
  if (!split.frames.empty()) render_frames(world, setup, plans, split.frames, log);
  for (const size_t index : split.tiles) {
    const JobStatistics stats = render_tile_job(world, setup, index, plans[index]);
    report_written(stats, setup.run);
    log.add(index, stats);
  }
}

void end_run(MpiWorld& world) {
  for (int k = 1; k < world.size(); ++k) world.send(k, encode(MessageType::kFinish));
}

}  // namespace mjray
