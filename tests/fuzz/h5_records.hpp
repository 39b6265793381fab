#pragma once
// The input format of the HDF5 fuzz targets (FCLib problems, restart files).
//
// Mutating the bytes of an HDF5 file mostly fuzzes the HDF5 library's own decoder, which
// moreau does not own and cannot fix. These targets fuzz what moreau reads instead: the
// input is a list of records, each an object of an HDF5 file (a group, a dataset of some
// type and shape with its values, an attribute), and the harness writes them as a valid
// HDF5 file that the reader under test then opens. libFuzzer's mutations thus become
// missing, extra, renamed, mistyped or misshapen datasets and absurd values (NaN, 1e308,
// 2^31 as an index), which is what a damaged or hand-made file holds.
//
//   input   := record*
//   record  := kind:u8 path:str [name:str if attribute] type:u8 rank:u8 dim:u16[rank] values
//   kind    := 0 dataset | 1 attribute (of the object at path; "" is the root) | 2 group
//   type    := 0 f64 | 1 i32 | 2 variable-length string | 3 fixed string (16) | 4 f32 | 5 i8 | 6 i64
//   str     := len:u8 byte[len]      (values of string type: len:u16 byte[len])
//   values  := one per element, little-endian; a short input is padded with zeros.
// Rank is taken modulo 3 and the element count capped (kMaxElements) so that no input
// asks for gigabytes. scripts/fuzz/encode_hdf5.py writes a real file in this format (the
// seed corpora); `moreau_fuzz_<target> --decode IN OUT.h5` writes one back.
#include <cstddef>
#include <cstdint>
#include <string>

namespace moreau_fuzz {

inline constexpr std::size_t kMaxElements = 1 << 18;

/// Writes the HDF5 file the records describe at `path` (replacing it). Records that cannot
/// be written (a dataset where a group is needed, a name given twice) are skipped.
/// Returns false if not even the file could be created.
bool write_records(const std::uint8_t* data, std::size_t size, const std::string& path);

/// A path in this process's scratch folder (in /dev/shm when there is one: the targets
/// write a file per input), removed with its folder when the process exits.
std::string scratch_file(const std::string& name);

}  // namespace moreau_fuzz
