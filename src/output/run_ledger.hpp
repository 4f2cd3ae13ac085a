#pragma once
// A run's dealings with the manifests of its output folder: what it may
// write there, what it can skip because it is already on disk, its journal
// while it runs, and the manifest it leaves (docs/farm.md).
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "output/manifest.hpp"
#include "output/manifest_journal.hpp"

namespace facet {

struct LedgerRequest {
    std::string folder;         // the manifest's
    std::string manifest_name;  // "manifest.json", or a part's partial_manifest_name
    Manifest header;            // this run's settings and provenance (job and part for a part)
    bool overwrite = false;     // other settings' manifests give way instead of refusing
};

// The folder's manifests and running journals against this run, without
// changing anything (render checks, --dry-run, validate). Throws
// invalid_input naming the file when:
// - manifest.json or a partial manifest there has other settings (unless
//   overwrite);
// - a partial manifest of the same settings covers some of this part's
//   frames under another name: the job was cut differently (unless overwrite);
// - a live run is writing there with other settings (always: --overwrite
//   cannot make two runs' files agree).
void check_manifest_claims(const LedgerRequest& request);

// One image as a manifest records it: its frame line and files.
struct RecordedImage {
    ManifestFrame frame;
    std::vector<ManifestFile> files;
};

class RunLedger {
  public:
    // Checks as check_manifest_claims, then (overwrite) removes the partial
    // manifests that stood in the way, and opens this run's journal.
    explicit RunLedger(LedgerRequest request);

    // What the folder's manifests and journals (live or dead) of the same
    // settings record for this image, if every one of `paths` (relative to
    // the folder) is recorded for it and is on disk with the recorded
    // SHA-256. Otherwise nullopt: the image must be rendered again.
    std::optional<RecordedImage> verified(int frame, const std::string& camera,
                                          const std::vector<std::string>& paths) const;

    // Appends one written image to the journal.
    void record(const Manifest& image) { journal_->append(image); }

    // Writes the manifest (merged with the one there unless overwrite), then
    // removes this run's journal and the dead ones of the same manifest,
    // which it supersedes. Returns the manifest's path.
    std::string finish(Manifest manifest);

  private:
    LedgerRequest request_;
    std::unique_ptr<ManifestJournal> journal_;
    // (camera, frame) -> what a same-settings record says about it.
    std::map<std::pair<std::string, int>, RecordedImage> recorded_;
};

}  // namespace facet
