// Durability of the result file: when a commit forces its data to the storage device (fsync).
//
// A commit publishes a complete HDF5 file under the final name (result_file.cpp). What the
// processes wrote is in the kernel's page cache the moment write(2) returns, so the published file
// survives the death of the run itself (SIGKILL, an MPI abort, a node's job being cancelled)
// without any fsync; only a crash of the operating system or a power loss can lose data the disk
// has not received yet. HDF5 forces every parallel H5Fflush to the device (MPI_File_sync, i.e.
// fsync on every rank), which costs 0.2..15 ms per commit depending on the disk's load, more than
// the integration step of a small dynamics model. On one process Sinew therefore lets a commit skip
// that sync and syncs when `-output_fsync_interval` seconds (default 10) have passed since the last
// synced commit: a crash of the machine loses at most that many seconds of steps. With several
// processes every commit syncs: HDF5's parallel flush relies on the collective sync to bring all
// ranks out of the flush together when one fails (a full disk hung 2 ranks without it).
#pragma once

namespace sinew {

/// While an instance with skip = true lives, MPI_File_sync (called by HDF5's H5Fflush on a
/// parallel file) returns at once without syncing. Collective use only: every rank must skip the
/// same calls (MPI_File_sync is collective).
class FileSyncSkip {
 public:
  explicit FileSyncSkip(bool skip);
  ~FileSyncSkip();
  FileSyncSkip(const FileSyncSkip&) = delete;
  FileSyncSkip& operator=(const FileSyncSkip&) = delete;

  /// MPI_File_sync calls made through Sinew's wrapper so far, and how many of them synced.
  static long calls();
  static long synced();

 private:
  bool previous_;
};

}  // namespace sinew
