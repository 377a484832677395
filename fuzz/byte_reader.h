// The fuzz input read front to back as the fields a harness needs; past the
// end everything is zero, so every input is a valid (if short) program.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool empty() const { return pos_ >= size_; }
  std::uint8_t Byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  std::uint32_t U32() {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = (v << 8) | Byte();
    return v;
  }
  double RawDouble() {
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits = (bits << 8) | Byte();
    double v;
    std::memcpy(&v, &bits, sizeof(v));
    return v;
  }
  std::string String(std::size_t max_len) {
    const std::size_t wanted = Byte() % (max_len + 1);  // before `left`: Byte() advances
    const std::size_t left = pos_ < size_ ? size_ - pos_ : 0;
    const std::size_t len = std::min(wanted, left);
    std::string s(reinterpret_cast<const char*>(data_ + pos_), len);
    pos_ += len;
    return s;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};
