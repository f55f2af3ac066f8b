#include "runtime/builtins/solid_cache.hpp"

#include <cstring>
#include <list>
#include <mutex>
#include <unordered_map>

namespace hlr::runtime {

void put_bits(double x, std::string& out) {
  char bytes[sizeof x];
  std::memcpy(bytes, &x, sizeof x);
  out.append(bytes, sizeof x);
}

namespace {

bool put_value(const Value& v, std::string& out) {
  out += static_cast<char>(v.kind());
  switch (v.kind()) {
    case ValueKind::None:
      return true;
    case ValueKind::Number:
      put_bits(v.as_number(), out);
      return true;
    case ValueKind::Bool:
      out += v.as_bool() ? '1' : '0';
      return true;
    case ValueKind::String:
      out += std::to_string(v.as_string().size()) + ':' + v.as_string();
      return true;
    case ValueKind::Vector: {
      const Vector3 p = v.as_vector();
      put_bits(p.x, out);
      put_bits(p.y, out);
      put_bits(p.z, out);
      return true;
    }
    case ValueKind::List: {
      const List& items = v.as_list();
      out += std::to_string(items.size()) + '[';
      for (const Value& item : items)
        if (!put_value(item, out)) return false;
      out += ']';
      return true;
    }
    case ValueKind::Range: {
      const RangeValue& r = v.as_range();
      put_bits(r.start, out);
      put_bits(r.step, out);
      out += std::to_string(r.count);
      return true;
    }
    default:
      return false;
  }
}

}  // namespace

std::optional<std::string> value_key(const Value& value) {
  std::string out;
  if (!put_value(value, out)) return std::nullopt;
  return out;
}

struct SolidCache::State {
  struct Entry {
    std::shared_ptr<const Solid> solid;
    std::shared_ptr<const Solid> source;  // keeps a placed solid's source alive: its address is in the key
    std::list<std::string>::iterator age;
  };
  std::size_t max_faces = 0;
  mutable std::mutex mutex;
  std::unordered_map<std::string, Entry> entries;
  std::list<std::string> ages;  // most recently used first
  SolidCacheStats stats;
};

SolidCache::SolidCache(std::size_t max_faces) : s_(std::make_unique<State>()) { s_->max_faces = max_faces; }

SolidCache::~SolidCache() = default;

std::shared_ptr<const Solid> SolidCache::lookup_or_make(const std::string& key,
                                                        const std::shared_ptr<const Solid>& source,
                                                        const Make& make) {
  {
    const std::lock_guard<std::mutex> lock(s_->mutex);
    if (const auto it = s_->entries.find(key); it != s_->entries.end()) {
      s_->ages.splice(s_->ages.begin(), s_->ages, it->second.age);
      ++s_->stats.hits;
      return it->second.solid;
    }
    ++s_->stats.misses;
  }
  // Made outside the lock: two frames may both make it, and the first kept wins (the same solid anyway).
  std::shared_ptr<const Solid> made = make();
  const std::size_t faces = made->faces.size();
  if (faces > s_->max_faces) return made;
  const std::lock_guard<std::mutex> lock(s_->mutex);
  if (const auto it = s_->entries.find(key); it != s_->entries.end()) return it->second.solid;
  while (!s_->ages.empty() && s_->stats.faces + faces > s_->max_faces) {
    const auto oldest = s_->entries.find(s_->ages.back());
    s_->stats.faces -= oldest->second.solid->faces.size();
    s_->entries.erase(oldest);
    s_->ages.pop_back();
  }
  s_->ages.push_front(key);
  s_->entries.emplace(key, State::Entry{made, source, s_->ages.begin()});
  s_->stats.faces += faces;
  return made;
}

std::shared_ptr<const Solid> SolidCache::generated(const std::string& function, const std::vector<Arg>& args,
                                                   const Make& make) {
  std::string key = "g" + std::to_string(function.size()) + ':' + function;
  for (const Arg& a : args) {
    key += std::to_string(a.label.size()) + ':' + a.label;
    if (!put_value(a.value, key)) return make();
  }
  return lookup_or_make(key, nullptr, make);
}

std::shared_ptr<const Solid> SolidCache::placed(const std::shared_ptr<const Solid>& source,
                                                const Affine3& world_from_object, const Make& make) {
  std::string key = "p" + std::to_string(reinterpret_cast<std::uintptr_t>(source.get())) + ':';
  for (const auto& row : world_from_object.m)
    for (const double x : row) put_bits(x, key);
  put_bits(world_from_object.t.x, key);
  put_bits(world_from_object.t.y, key);
  put_bits(world_from_object.t.z, key);
  return lookup_or_make(key, source, make);
}

std::shared_ptr<const Solid> SolidCache::derived(const std::shared_ptr<const Solid>& source,
                                                 const std::string& how, const Make& make) {
  return lookup_or_make("d" + std::to_string(reinterpret_cast<std::uintptr_t>(source.get())) + ':' + how,
                        source, make);
}

SolidCacheStats SolidCache::stats() const {
  const std::lock_guard<std::mutex> lock(s_->mutex);
  SolidCacheStats out = s_->stats;
  out.entries = s_->entries.size();
  return out;
}

void SolidCache::clear() {
  const std::lock_guard<std::mutex> lock(s_->mutex);
  s_->entries.clear();
  s_->ages.clear();
  s_->stats = {};
}

SolidCache& SolidCache::shared() {
  static SolidCache cache(2'000'000);
  return cache;
}

}  // namespace hlr::runtime
