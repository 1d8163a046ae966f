#pragma once
/// Building and reading the bytes of a message: fixed-size values and length-prefixed runs,
/// in the sender's byte order (every rank runs the same binary on the same kind of machine).

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
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
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

/// Reads what a ByteWriter wrote, in the same order; throws std::runtime_error past the end.
class ByteReader {
 public:
  explicit ByteReader(const std::string& bytes) : bytes_(bytes) {}

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
  [[noreturn]] static void truncated() { throw std::runtime_error("a message between ranks was cut short"); }

  const std::string& bytes_;
  size_t offset_ = 0;
};

}  // namespace mjray
