#pragma once
// The CRC-32 check of a ZIP archive, the container of LibTorch's files (policy.pt,
// checkpoint.pt). LibTorch's reader skips it (it is built with
// MINIZ_DISABLE_ZIP_READER_CRC32_CHECKS), so a file whose bytes changed inside a tensor
// (a disk error, a bad copy) loads without a word; the tools check it before they load.
#include <filesystem>
#include <string>

namespace passageMesh {

// "" when every stored member's data has the CRC-32 the central directory records (ZIP
// and ZIP64 layouts; members stored uncompressed, as LibTorch writes them: compressed ones
// are not checked); else what is wrong, in words ("member 'archive/data/3' does not match
// its checksum (the file is corrupt)"). A file that cannot be read, or is no ZIP archive,
// is described too.
std::string zipChecksumProblem(const std::filesystem::path& file);

}  // namespace passageMesh
