#include "messages.h"
#include "mjray/core/byte_buffer.h"

#include <stdexcept>


namespace mjray {

namespace {

ByteWriter start(MessageType type) {
  ByteWriter w;
  w.put(type);
  return w;
}

/// A reader past the type byte, which must be `type`.
ByteReader reader_of(const std::string& bytes, MessageType type) {
  if (type_of(bytes) != type) throw std::runtime_error("a message between ranks has an unexpected type");
  ByteReader r(bytes, "a message between ranks");
  r.get<MessageType>();
  return r;
}

void put_rank(ByteWriter& w, const RankStatistics& s) {
  w.put(int32_t(s.rank)).put_string(s.host).put(int32_t(s.threads)).put(s.seconds_load).put(s.seconds_build);
  w.put(s.seconds_rendering).put(s.tiles).put(s.pixels_supersampled).put(s.rays).put(s.bytes_sent);
}

RankStatistics get_rank(ByteReader& r) {
  RankStatistics s;
  s.rank = r.get<int32_t>();
  s.host = r.get_string();
  s.threads = r.get<int32_t>();
  s.seconds_load = r.get<double>();
  s.seconds_build = r.get<double>();
  s.seconds_rendering = r.get<double>();
  s.tiles = r.get<uint64_t>();
  s.pixels_supersampled = r.get<uint64_t>();
  s.rays = r.get<uint64_t>();
  s.bytes_sent = r.get<uint64_t>();
  return s;
}

// Every field of JobStatistics travels, so that a frame rendered elsewhere reports as one
// rendered here: a field added to JobStatistics is added here too.
void put_job(ByteWriter& w, const JobStatistics& s) {
  w.put_string(s.image).put(s.seconds_parse).put(s.seconds_build).put(s.seconds_render).put(s.primitives);
  w.put_string(s.accel).put(s.render.rays).put(s.render.seconds).put(int32_t(s.render.threads));
  w.put(s.render.pixels_supersampled).put(int32_t(s.render.antialias_passes)).put(uint8_t(s.render.subdivided));
  w.put(s.peak_rss_bytes);
  w.put(uint64_t(s.ranks.size()));
  for (const RankStatistics& rank : s.ranks) put_rank(w, rank);
}

JobStatistics get_job(ByteReader& r) {
  JobStatistics s;
  s.image = r.get_string();
  s.seconds_parse = r.get<double>();
  s.seconds_build = r.get<double>();
  s.seconds_render = r.get<double>();
  s.primitives = r.get<uint32_t>();
  s.accel = r.get_string();
  s.render.rays = r.get<RayCounters>();
  s.render.seconds = r.get<double>();
  s.render.threads = r.get<int32_t>();
  s.render.pixels_supersampled = r.get<uint64_t>();
  s.render.antialias_passes = r.get<int32_t>();
  s.render.subdivided = r.get<uint8_t>() != 0;
  s.peak_rss_bytes = r.get<uint64_t>();
  const auto ranks = r.get<uint64_t>();
  for (uint64_t i = 0; i < ranks; ++i) s.ranks.push_back(get_rank(r));
  return s;
}

}  // namespace

MessageType type_of(const std::string& bytes) {
  if (bytes.empty()) throw std::runtime_error("an empty message between ranks");
  return MessageType(uint8_t(bytes[0]));
}

std::string encode(MessageType type) { return start(type).take(); }

std::string encode(const TileJobMessage& m) { return start(MessageType::kTileJob).put(m.job).put(m.tile_size).take(); }

std::string encode(const UnitsMessage& m) {
  ByteWriter w = start(MessageType::kUnits);
  w.put(m.phase).put(uint64_t(m.units.size()));
  for (const WorkUnit& u : m.units) w.put(u.kind).put(u.id).put_vector(u.pixels).put(u.pass);
  return w.take();
}

std::string encode(const FrameJobMessage& m) { return start(MessageType::kFrameJob).put(m.job).put_string(m.state).take(); }

std::string encode(const ReadyMessage& m) {
  return start(MessageType::kReady).put(m.job).put(m.threads).put(m.seconds_build).take();
}

std::string encode(const ResultMessage& m) {
  return start(MessageType::kResult).put(m.phase).put(m.kind).put(m.id).put(m.rays).put_vector(m.values).take();
}

std::string encode(const RankStatistics& m) {
  ByteWriter w = start(MessageType::kJobReport);
  put_rank(w, m);
  return w.take();
}

std::string encode(const FrameDoneMessage& m) {
  ByteWriter w = start(MessageType::kFrameDone);
  w.put(m.job).put(uint8_t(m.finished)).put(int32_t(m.image.width())).put(int32_t(m.image.height()));
  w.put_vector(m.image.pixels()).put_string(m.checkpoint);
  put_job(w, m.stats);
  return w.take();
}

std::string encode(const FailedMessage& m) { return start(MessageType::kFailed).put_string(m.text).take(); }

TileJobMessage decode_tile_job(const std::string& bytes) {
  ByteReader r = reader_of(bytes, MessageType::kTileJob);
  TileJobMessage m;
  m.job = r.get<uint32_t>();
  m.tile_size = r.get<int32_t>();
  return m;
}

UnitsMessage decode_units(const std::string& bytes) {
  ByteReader r = reader_of(bytes, MessageType::kUnits);
  UnitsMessage m;
  m.phase = r.get<uint32_t>();
  const auto count = r.get<uint64_t>();
  for (uint64_t i = 0; i < count; ++i) {
    WorkUnit u;
    u.kind = r.get<WorkUnit::Kind>();
    u.id = r.get<int32_t>();
    u.pixels = r.get_vector<int32_t>();
    u.pass = r.get<PixelPass>();
    m.units.push_back(std::move(u));
  }
  return m;
}

FrameJobMessage decode_frame_job(const std::string& bytes) {
  ByteReader r = reader_of(bytes, MessageType::kFrameJob);
  FrameJobMessage m;
  m.job = r.get<uint32_t>();
  m.state = r.get_string();
  return m;
}

ReadyMessage decode_ready(const std::string& bytes) {
  ByteReader r = reader_of(bytes, MessageType::kReady);
  ReadyMessage m;
  m.job = r.get<uint32_t>();
  m.threads = r.get<int32_t>();
  m.seconds_build = r.get<double>();
  return m;
}

ResultMessage decode_result(const std::string& bytes) {
  ByteReader r = reader_of(bytes, MessageType::kResult);
  ResultMessage m;
  m.phase = r.get<uint32_t>();
  m.kind = r.get<WorkUnit::Kind>();
  m.id = r.get<int32_t>();
  m.rays = r.get<RayCounters>();
  m.values = r.get_vector<FilmPixel>();
  return m;
}

RankStatistics decode_job_report(const std::string& bytes) {
  ByteReader r = reader_of(bytes, MessageType::kJobReport);
  return get_rank(r);
}

FrameDoneMessage decode_frame_done(const std::string& bytes) {
  ByteReader r = reader_of(bytes, MessageType::kFrameDone);
  FrameDoneMessage m;
  m.job = r.get<uint32_t>();
  m.finished = r.get<uint8_t>() != 0;
  const auto width = r.get<int32_t>(), height = r.get<int32_t>();
  const std::vector<Color> pixels = r.get_vector<Color>();
  if (width < 0 || height < 0 || pixels.size() != size_t(width) * size_t(height))
    throw std::runtime_error("a frame sent between ranks has the wrong size");
  m.image = Image(width, height);
  std::copy(pixels.begin(), pixels.end(), m.image.data());
  m.checkpoint = r.get_string();
  m.stats = get_job(r);
  return m;
}

FailedMessage decode_failed(const std::string& bytes) { return {reader_of(bytes, MessageType::kFailed).get_string()}; }

}  // namespace mjray
