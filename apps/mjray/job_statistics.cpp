#include "job_statistics.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <utility>

#include <sys/resource.h>

#include "mjray/core/error.h"
#include "mjray/io/atomic_file.h"
#include "mjray/job/job_outputs.h"

namespace mjray {

double JobStatistics::rays_per_second() const {
  return render.seconds > 0 ? double(render.rays.total()) / render.seconds : 0;
}

uint64_t peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return uint64_t(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

namespace {

constexpr double kMiB = 1024.0 * 1024.0;

/// The summary's photon lines, or nothing without photon maps.
std::string photon_text(const JobStatistics& s) {
  if (!s.photons) return "";
  const PhotonStatistics& p = *s.photons;
  char text[512];
  std::snprintf(text, sizeof text,
                "  photons   caustic %llu emitted, %llu stored; global %llu emitted, %llu stored, %llu irradiance "
                "samples; %.1f MiB\n"
                "  photon pass %.3fs: trace %.3fs (%llu rays), kd-trees %.3fs, irradiance %.3fs\n",
                (unsigned long long)p.caustic_emitted, (unsigned long long)p.caustic_stored,
                (unsigned long long)p.global_emitted, (unsigned long long)p.global_stored,
                (unsigned long long)p.irradiance_samples, double(p.memory_bytes) / kMiB, p.seconds(), p.seconds_trace,
                (unsigned long long)p.rays, p.seconds_build, p.seconds_irradiance);
  return text;
}

/// The photon fields of a job's JSON object (with a leading comma), or nothing.
std::string photon_json(const JobStatistics& s) {
  if (!s.photons) return "";
  const PhotonStatistics& p = *s.photons;
  const std::pair<const char*, double> fields[] = {
      {"photons_caustic_emitted", double(p.caustic_emitted)}, {"photons_caustic_stored", double(p.caustic_stored)},
      {"photons_global_emitted", double(p.global_emitted)},   {"photons_global_stored", double(p.global_stored)},
      {"photon_irradiance_samples", double(p.irradiance_samples)}, {"photon_rays", double(p.rays)},
      {"seconds_photons", p.seconds()},                        {"seconds_photon_trace", p.seconds_trace},
      {"seconds_photon_build", p.seconds_build},               {"seconds_photon_irradiance", p.seconds_irradiance},
      {"photon_map_bytes", double(p.memory_bytes)}};
  std::string out;
  for (const auto& [key, value] : fields) {
    char field[96];
    std::snprintf(field, sizeof field, ", \"%s\": %.10g", key, value);
    out += field;
  }
  return out;
}

/// What anti-aliasing did to the pixels, for the statistics' pixels line.
std::string antialiasing_text(const RenderStats& r) {
  if (r.subdivided) return "subdivided from their corners in the first pass (--aa-method subdivide)";
  return std::to_string(r.pixels_supersampled) + " supersampled in " + std::to_string(r.antialias_passes) +
         " anti-aliasing passes";
}

}  // namespace

std::string summary_text(const JobStatistics& s) {
  // Appended piece by piece: GCC 12 warns falsely on "text" + a temporary string (its PR 105651).
  std::string grid;
  if (s.grid_resolution) grid.append(" ").append(std::to_string(s.grid_resolution)).append("³");
  char text[1024];
  std::snprintf(text, sizeof text,
                "mjray: wrote %s\n"
                "  time      %.3fs total: parse %.3fs, build %.3fs (%s%s, %u primitives), render %.3fs on %d threads\n"
                "  rays      %llu primary, %llu secondary, %llu shadow: %.2f M rays/s\n"
                "  pixels    %s\n"
                "  memory    %.1f MiB peak\n",
                s.image.c_str(), s.seconds_total(), s.seconds_parse, s.seconds_build, s.accel.c_str(), grid.c_str(), s.primitives,
                s.seconds_render, s.render.threads, (unsigned long long)s.render.rays.primary,
                (unsigned long long)s.render.rays.secondary, (unsigned long long)s.render.rays.shadow,
                s.rays_per_second() / 1e6, antialiasing_text(s.render).c_str(), double(s.peak_rss_bytes) / kMiB);
  std::string summary = text + photon_text(s);
  for (const RankStatistics& r : s.ranks) {
    std::snprintf(text, sizeof text,
                  "  rank %-4d %s: load %.3fs, build %.3fs, rendering %.3fs on %d threads, %llu tiles, "
                  "%llu pixels supersampled, %.2f MB sent\n",
                  r.rank, r.host.c_str(), r.seconds_load, r.seconds_build, r.seconds_rendering, r.threads,
                  (unsigned long long)r.tiles, (unsigned long long)r.pixels_supersampled, double(r.bytes_sent) / 1e6);
    summary += text;
  }
  return summary;
}

std::string frame_line(const JobStatistics& s, const std::string& frame, bool detailed) {
  char text[512];
  if (!detailed) {
    std::snprintf(text, sizeof text, "mjray: wrote %s (%s, %.2fs)\n", s.image.c_str(), frame.c_str(), s.seconds_total());
    return text;
  }
  std::snprintf(text, sizeof text,
                "mjray: wrote %s (%s): %.3fs (build %.3fs, render %.3fs), %llu rays at %.2f M rays/s, %s, "
                "%.1f MiB peak\n",
                s.image.c_str(), frame.c_str(), s.seconds_total(), s.seconds_build, s.seconds_render,
                (unsigned long long)s.render.rays.total(), s.rays_per_second() / 1e6,
                s.render.subdivided ? "pixels subdivided"
                                    : (std::to_string(s.render.pixels_supersampled) + " pixels supersampled").c_str(),
                double(s.peak_rss_bytes) / (1024.0 * 1024.0));
  return text;
}

std::string animation_summary(const std::vector<JobStatistics>& frames, size_t kept, bool detailed) {
  JobStatistics all;
  all.seconds_parse = frames.empty() ? 0 : frames.front().seconds_parse;
  for (const JobStatistics& s : frames) {
    all.seconds_build += s.seconds_build;
    all.seconds_render += s.seconds_render;
    all.render.seconds += s.render.seconds;
    all.render.rays += s.render.rays;
    all.render.threads = s.render.threads;
    all.render.pixels_supersampled += s.render.pixels_supersampled;
    all.render.antialias_passes += s.render.antialias_passes;
    all.render.subdivided = all.render.subdivided || s.render.subdivided;
    all.primitives = std::max(all.primitives, s.primitives);
    all.peak_rss_bytes = std::max(all.peak_rss_bytes, s.peak_rss_bytes);
    if (all.accel.empty()) all.accel = s.accel;
    if (s.photons) {
      PhotonStatistics& p = all.photons ? *all.photons : all.photons.emplace();
      p.caustic_emitted += s.photons->caustic_emitted;
      p.caustic_stored += s.photons->caustic_stored;
      p.global_emitted += s.photons->global_emitted;
      p.global_stored += s.photons->global_stored;
      p.irradiance_samples += s.photons->irradiance_samples;
      p.rays += s.photons->rays;
      p.seconds_trace += s.photons->seconds_trace;
      p.seconds_build += s.photons->seconds_build;
      p.seconds_irradiance += s.photons->seconds_irradiance;
      p.memory_bytes = std::max(p.memory_bytes, s.photons->memory_bytes);
    }
  }
  char head[256];
  const std::string kept_text = kept > 0 ? " (" + std::to_string(kept) + " kept)" : "";
  std::snprintf(head, sizeof head, "mjray: rendered %zu frame%s%s in %.3fs\n", frames.size(), frames.size() == 1 ? "" : "s",
                kept_text.c_str(), all.seconds_total());
  if (!detailed) return head;
  // The paragraph of one image, over every frame: its first line replaced by the head.
  const std::string paragraph = summary_text(all);
  return head + paragraph.substr(paragraph.find('\n') + 1);
}

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    } else out += c;
  }
  return out + "\"";
}

namespace {

/// The "ranks" member of a job under MPI: one object per rank.
std::string ranks_json(const std::vector<RankStatistics>& ranks) {
  std::string out = ", \"ranks\": [";
  for (size_t i = 0; i < ranks.size(); ++i) {
    const RankStatistics& r = ranks[i];
    char numbers[512];
    std::snprintf(numbers, sizeof numbers,
                  "\"rank\": %d, \"threads\": %d, \"seconds_load\": %.6f, \"seconds_build\": %.6f, "
                  "\"seconds_rendering\": %.6f, \"tiles\": %llu, \"pixels_supersampled\": %llu, \"rays\": %llu, "
                  "\"bytes_sent\": %llu",
                  r.rank, r.threads, r.seconds_load, r.seconds_build, r.seconds_rendering, (unsigned long long)r.tiles,
                  (unsigned long long)r.pixels_supersampled, (unsigned long long)r.rays, (unsigned long long)r.bytes_sent);
    out += std::string(i ? ", " : "") + "{" + numbers + ", \"host\": " + json_string(r.host) + "}";
  }
  return out + "]";
}

}  // namespace

std::string statistics_json(const JobStatistics& s) {
  char numbers[1024];
  std::snprintf(numbers, sizeof numbers,
                "\"seconds_total\": %.6f, \"seconds_parse\": %.6f, \"seconds_build\": %.6f, "
                "\"seconds_render\": %.6f, \"primitives\": %u, \"threads\": %d, \"rays_primary\": %llu, "
                "\"rays_secondary\": %llu, \"rays_shadow\": %llu, \"rays_per_second\": %.1f, "
                "\"pixels_supersampled\": %llu, \"peak_rss_bytes\": %llu, \"grid_resolution\": %d",
                s.seconds_total(), s.seconds_parse, s.seconds_build, s.seconds_render, s.primitives,
                s.render.threads, (unsigned long long)s.render.rays.primary,
                (unsigned long long)s.render.rays.secondary, (unsigned long long)s.render.rays.shadow,
                s.rays_per_second(), (unsigned long long)s.render.pixels_supersampled,
                (unsigned long long)s.peak_rss_bytes, s.grid_resolution);
  std::string out = "{\"image\": " + json_string(s.image) + ", \"accel\": " + json_string(s.accel) + ", " + numbers;
  if (s.render.subdivided) out += ", \"antialias_method\": \"subdivide\"";  // pixels_supersampled is then 0
  out += photon_json(s);
  if (!s.ranks.empty()) out += ranks_json(s.ranks);
  return out + "}";
}

void write_statistics_json(const std::vector<JobStatistics>& jobs, const std::filesystem::path& path) {
  std::string out = "[\n";
  for (size_t i = 0; i < jobs.size(); ++i) {
    out += "  " + statistics_json(jobs[i]);
    out += i + 1 < jobs.size() ? ",\n" : "\n";
  }
  out += "]\n";
  write_file_atomically(path, out);
}


}  // namespace mjray
