// Which pages the heap goes on (runtime/base/heap_pages.hpp): small ones only where a virtio balloon
// reports free pages to the host. The devices here are folders written as sysfs lays them out, with the
// real files' formats (a hexadecimal device id; one character per feature bit, bit 0 first).
#include "runtime/base/heap_pages.hpp"

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "tests/support/temp_dir.hpp"

namespace hlr::runtime {
namespace {

// 64 feature bits, '1' at the positions given.
std::string features(std::initializer_list<int> set) {
  std::string bits(64, '0');
  for (int b : set) bits[static_cast<std::size_t>(b)] = '1';
  return bits + "\n";
}

void add_device(const test::TempDir& sys, const std::string& name, const std::string& id,
                const std::string& feature_bits) {
  sys.write(name + "/device", id + "\n");
  sys.write(name + "/features", feature_bits);
}

TEST(HeapPages, ABalloonThatReportsFreePagesMeansSmallPages) {
  test::TempDir sys("heap-pages-reporting");
  add_device(sys, "virtio0", "0x0002", features({0, 1, 5}));  // a block device: bit 5 means something else
  add_device(sys, "virtio1", "0x0005", features({1, 2, 5, 7}));
  EXPECT_TRUE(host_takes_back_free_memory(sys.path().c_str()));
  EXPECT_STREQ(heap_page_tunable(sys.path().c_str()), "glibc.malloc.hugetlb=0");
}

TEST(HeapPages, OtherwiseHugePages) {
  test::TempDir sys("heap-pages-other");
  add_device(sys, "virtio0", "0x0002", features({5}));     // bit 5 of a device that is not a balloon
  add_device(sys, "virtio1", "0x0005", features({1, 2}));  // a balloon that does not report
  EXPECT_FALSE(host_takes_back_free_memory(sys.path().c_str()));
  EXPECT_STREQ(heap_page_tunable(sys.path().c_str()), "glibc.malloc.hugetlb=1");
}

TEST(HeapPages, NoVirtioAtAllOrUnreadableFilesMeanHugePages) {
  test::TempDir sys("heap-pages-none");
  EXPECT_FALSE(host_takes_back_free_memory((sys.path() / "missing").c_str()));
  EXPECT_FALSE(host_takes_back_free_memory(sys.path().c_str()));  // an empty folder
  sys.write("virtio0/device", "0x0005\n");                        // a balloon without its features file
  EXPECT_FALSE(host_takes_back_free_memory(sys.path().c_str()));
  sys.write("virtio1/device", "0x0005\n");
  sys.write("virtio1/features", "0110\n");  // too short to hold bit 5
  EXPECT_FALSE(host_takes_back_free_memory(sys.path().c_str()));
  sys.write("virtio2/device", "garbage\n");
  sys.write("virtio2/features", features({5}));
  EXPECT_FALSE(host_takes_back_free_memory(sys.path().c_str()));
}

}  // namespace
}  // namespace hlr::runtime
