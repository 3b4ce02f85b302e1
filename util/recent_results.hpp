#pragma once
// The results of a pure function for the keys it was given last: a
// direct-mapped table (a key's slot from a hash of its bytes; a new key
// takes the slot of the one before). A key is found only when all its bytes
// match, so a value found is the one the function gave for these very bytes
// (0.0 and -0.0, or two NaNs with different payloads, are different keys):
// a caller that asks only while the function stays the same gets the bytes
// it would have computed. clear() when the function changes.
// Key: trivially copyable, its size a multiple of four bytes and no padding
// (its bytes are its value).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include "util/check.hpp"

namespace mpr {

template <typename Key, typename Value, std::size_t kSlots>
class RecentResults {
  static_assert(std::is_trivially_copyable_v<Key> && sizeof(Key) % sizeof(std::uint32_t) == 0);
  static_assert(kSlots > 1 && (kSlots & (kSlots - 1)) == 0, "a power of two");

 public:
  // Forgets every key at once (the slots' generation moves on).
  void clear() {
    if (++generation_ != 0) return;
    for (Slot& s : slots_) s.generation = 0;  // after 2^32 clears
    generation_ = 1;
  }

  // The value for `key`: the one stored since the last clear(), or
  // compute(key), stored.
  template <typename Compute>
  const Value& get(const Key& key, Compute&& compute) {
    if (slots_.empty()) slots_.resize(kSlots);  // the table only where it is used
    Slot& s = slots_[slotOf(key)];
    if (s.generation == generation_ && std::memcmp(&s.key, &key, sizeof(Key)) == 0) {
      if constexpr (kCheckCaches) {
        static_assert(std::is_trivially_copyable_v<Value>, "compared by its bytes");
        const Value fresh = compute(key);
        MPR_CHECK(std::memcmp(&fresh, &s.value, sizeof(Value)) == 0);
      }
      return s.value;
    }
    s.value = compute(key);
    s.key = key;
    s.generation = generation_;
    return s.value;
  }

 private:
  struct Slot {
    Key key;
    std::uint32_t generation = 0;
    Value value;
  };

  // Each pair of words times its own odd constant, the products summed and
  // mixed once: multiplies side by side, not a chain of one per word (a
  // vertex's twelve words were a chain of twelve, per vertex of a trace).
  static std::size_t slotOf(const Key& key) {
    constexpr std::size_t kWords = sizeof(Key) / sizeof(std::uint32_t);
    static constexpr std::uint64_t kOdd[8] = {0x9E3779B97F4A7C15ull, 0xC2B2AE3D27D4EB4Full, 0x165667B19E3779F9ull,
                                              0xD6E8FEB86659FD93ull, 0xFF51AFD7ED558CCDull, 0xC4CEB9FE1A85EC53ull,
                                              0x85EBCA77C2B2AE63ull, 0x27D4EB2F165667C5ull};
    std::uint32_t words[kWords];
    std::memcpy(words, &key, sizeof(Key));
    std::uint64_t h = 0;
    for (std::size_t i = 0; i < kWords; i += 2) {
      const std::uint64_t pair = words[i] | (i + 1 < kWords ? std::uint64_t{words[i + 1]} << 32 : 0);
      h += pair * kOdd[(i / 2) % 8];
    }
    h ^= h >> 31;
    h *= 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(h >> 40) & (kSlots - 1);
  }

  std::vector<Slot> slots_;
  std::uint32_t generation_ = 1;
};

}  // namespace mpr
