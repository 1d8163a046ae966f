#pragma once
/// Building and reading byte strings: fixed-size values and length-prefixed runs in this
/// machine's byte order (resume states, and messages between ranks that run the same binary
/// on the same kind of machine).

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace mjray {

/// Appends values to a byte string.
class ByteWriter {
 public:
  template <class T>
  ByteWriter& put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
    return *this;
  }
  /// A count, then the elements.
  template <class T>
  ByteWriter& put_vector(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put(uint64_t(values.size()));
    bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    return *this;
  }
  ByteWriter& put_string(const std::string& text) {
    put(uint64_t(text.size()));
    bytes_ += text;
    return *this;
  }
  /// `n` bytes as they are, with no count.
  ByteWriter& put_bytes(const void* data, size_t n) {
    bytes_.append(static_cast<const char*>(data), n);
    return *this;
  }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

/// Thrown by ByteReader when the bytes end before what they should hold.
struct TruncatedBytes : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Reads what a ByteWriter wrote, in the same order; throws TruncatedBytes ("WHAT was cut
/// short") past the end.
class ByteReader {
 public:
  explicit ByteReader(const std::string& bytes, std::string what = "a byte string")
      : bytes_(bytes), what_(std::move(what)) {}

  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    copy(&value, sizeof value);
    return value;
  }
  template <class T>
  std::vector<T> get_vector() {
    const auto count = get<uint64_t>();
    if (count > (bytes_.size() - offset_) / sizeof(T)) truncated();
    std::vector<T> values(count);
    copy(values.data(), count * sizeof(T));
    return values;
  }
  /// `n` bytes as they are (what put_bytes wrote).
  void get_bytes(void* out, size_t n) { copy(out, n); }
  bool at_end() const { return offset_ == bytes_.size(); }
  std::string get_string() {
    const auto count = get<uint64_t>();
    if (count > bytes_.size() - offset_) truncated();
    std::string text = bytes_.substr(offset_, count);
    offset_ += count;
    return text;
  }

 private:
  void copy(void* out, size_t n) {
    if (n > bytes_.size() - offset_) truncated();
    if (n == 0) return;  // `out` may be an empty vector's null data(): memcpy must not see it
    std::memcpy(out, bytes_.data() + offset_, n);
    offset_ += n;
  }
  [[noreturn]] void truncated() const { throw TruncatedBytes(what_ + " was cut short"); }

  const std::string& bytes_;
  std::string what_;
  size_t offset_ = 0;
};

}  // namespace mjray
