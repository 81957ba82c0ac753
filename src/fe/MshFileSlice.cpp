#include "fe/MshFileSlice.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <memory>
#include <set>
#include <string_view>
#include <utility>

#include "signorini/core/Error.hpp"

namespace signorini {
namespace {

// Gmsh's element types of the linear simplices: line, triangle, tetrahedron.
int simplexType(int dim) { return dim == 1 ? 1 : dim == 2 ? 2 : 4; }

// The file's lines through a buffer, so that a scan keeps a few MiB whatever the file's size
// (a mapping would count the whole file in the resident set of every rank).
class LineReader {
 public:
  explicit LineReader(const std::string& path) : file_(std::fopen(path.c_str(), "rb"), &std::fclose), buffer_(1 << 22) {
    if (!file_) throw InputError("Gmsh mesh file '" + path + "': cannot open it (missing, not a regular file or unreadable)");
  }

  // The next line without its end ("\n" or "\r\n"); false at the end of the file.
  bool next(std::string_view& line) {
    for (;;) {
      if (const void* found = std::memchr(buffer_.data() + begin_, '\n', end_ - begin_)) {
        const std::size_t newline = static_cast<const char*>(found) - buffer_.data();
        line = lineAt(begin_, newline);
        begin_ = newline + 1;
        return true;
      }
      if (!refill()) {
        if (begin_ == end_) return false;
        line = lineAt(begin_, end_);
        begin_ = end_;
        return true;
      }
    }
  }

  // Skips `count` lines; false if the file ends first.
  bool skip(long long count) {
    std::string_view line;
    for (long long i = 0; i < count; ++i)
      if (!next(line)) return false;
    return true;
  }

  long long offset() const { return bufferOffset_ + static_cast<long long>(begin_); }

  void seek(long long offset) {
    fseeko(file_.get(), static_cast<off_t>(offset), SEEK_SET);
    bufferOffset_ = offset;
    begin_ = end_ = 0;
    atEnd_ = false;
  }

 private:
  std::string_view lineAt(std::size_t begin, std::size_t end) const {
    if (end > begin && buffer_[end - 1] == '\r') --end;
    return std::string_view(buffer_.data() + begin, end - begin);
  }

  // Moves the unread bytes to the front and reads more after them; false at the end.
  bool refill() {
    if (atEnd_) return false;
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    bufferOffset_ += static_cast<long long>(begin_);
    end_ -= begin_;
    begin_ = 0;
    if (end_ == buffer_.size()) buffer_.resize(2 * buffer_.size());  // a line longer than the buffer
    const std::size_t read = std::fread(buffer_.data() + end_, 1, buffer_.size() - end_, file_.get());
    end_ += read;
    atEnd_ = read == 0;
    return read > 0;
  }

  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_;
  std::vector<char> buffer_;
  std::size_t begin_ = 0, end_ = 0;
  long long bufferOffset_ = 0;
  bool atEnd_ = false;
};

// The numbers of a line, read one after the other; ok() turns false at the first that is
// missing or malformed.
class Numbers {
 public:
  explicit Numbers(std::string_view line) : at_(line.data()), end_(line.data() + line.size()) {}

  template <class T>
  T next() {
    while (at_ < end_ && (*at_ == ' ' || *at_ == '\t')) ++at_;
    T value{};
    const auto [stop, error] = std::from_chars(at_, end_, value);
    if (error != std::errc() || stop == at_) ok_ = false;
    at_ = stop;
    return value;
  }

  bool ok() const { return ok_; }

 private:
  const char* at_;
  const char* end_;
  bool ok_ = true;
};

struct ElementBlockHeader {
  int dim = 0, entity = 0, type = 0;
  long long count = 0;
  long long firstLine = 0;  // offset of the block's first element line
};

// What the headers of a file say: enough to decide whether the reader can read it and to
// find each rank's slice without parsing the rest.
struct MshLayout {
  std::string unsupported;                                       // why the reader cannot read it; "" if it can
  std::map<std::pair<int, int>, std::string> names;              // (dim, physical tag) -> name
  std::map<std::pair<int, int>, std::vector<int>> physicalsOf;   // (dim, entity tag) -> physical tags
  bool hasEntities = false;
  long long nodesStart = -1;                                     // offset of the first node block
  long long numNodeBlocks = 0, minNodeTag = 0, maxNodeTag = 0;
  std::vector<ElementBlockHeader> elementBlocks;
};

class LayoutScanner {
 public:
  explicit LayoutScanner(const std::string& path) : reader_(path) {}

  MshLayout scan() {
    std::string_view line;
    bool first = true;
    while (layout_.unsupported.empty() && reader_.next(line)) {
      if (line.empty()) continue;
      if (first && line != "$MeshFormat") unsupported("it does not start with $MeshFormat");
      if (!layout_.unsupported.empty()) break;
      first = false;
      section(std::string(line));
    }
    if (layout_.unsupported.empty() && (layout_.nodesStart < 0 || layout_.elementBlocks.empty()))
      unsupported("it has no $Nodes or no $Elements section");
    return std::move(layout_);
  }

 private:
  void unsupported(const std::string& why) {
    if (layout_.unsupported.empty()) layout_.unsupported = why;
  }

  void section(const std::string& name) {
    if (name == "$MeshFormat") return format();
    if (name == "$PhysicalNames") return physicalNames();
    if (name == "$Entities") return entities();
    if (name == "$PartitionedEntities") return unsupported("it is a partitioned mesh");
    if (name == "$Nodes") return nodes();
    if (name == "$Elements") return elements();
    if (name.empty() || name[0] != '$') return unsupported("a line outside every section");
    skipTo("$End" + name.substr(1));
  }

  // Reads the next line; marks the file unsupported where it ends.
  bool line(std::string_view& text) {
    if (reader_.next(text)) return true;
    unsupported("it ends inside a section");
    return false;
  }

  void skipTo(const std::string& end) {
    std::string_view text;
    while (line(text))
      if (text == end) return;
  }

  void format() {
    std::string_view text;
    if (!line(text)) return;
    Numbers numbers(text);
    const double version = numbers.next<double>();
    const int fileType = numbers.next<int>();
    if (!numbers.ok() || version != 4.1 || fileType != 0)
      return unsupported("it is not in the MSH 4.1 ASCII format");
    skipTo("$EndMeshFormat");
  }

  void physicalNames() {
    std::string_view text;
    if (!line(text)) return;
    Numbers count(text);
    const long long n = count.next<long long>();
    for (long long i = 0; count.ok() && i < n && line(text); ++i) {
      Numbers numbers(text);
      const int dim = numbers.next<int>(), tag = numbers.next<int>();
      const auto open = text.find('"'), close = text.rfind('"');
      if (!numbers.ok() || open == std::string_view::npos || close <= open)
        return unsupported("a malformed $PhysicalNames line");
      layout_.names[{dim, tag}] = std::string(text.substr(open + 1, close - open - 1));
    }
    skipTo("$EndPhysicalNames");
  }

  void entities() {
    std::string_view text;
    if (!line(text)) return;
    Numbers counts(text);
    long long count[4];
    for (long long& c : count) c = counts.next<long long>();
    if (!counts.ok()) return unsupported("a malformed $Entities section");
    for (int dim = 0; dim < 4; ++dim)
      for (long long i = 0; i < count[dim] && line(text); ++i) {
        Numbers numbers(text);
        const int tag = numbers.next<int>();
        for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) numbers.next<double>();  // a point, or a bounding box
        const long long numPhysicals = numbers.next<long long>();
        std::vector<int>& physicals = layout_.physicalsOf[{dim, tag}];
        for (long long p = 0; numbers.ok() && p < numPhysicals; ++p) physicals.push_back(numbers.next<int>());
        if (!numbers.ok() || numPhysicals < 0) return unsupported("a malformed $Entities section");
      }
    layout_.hasEntities = true;
    skipTo("$EndEntities");
  }

  void nodes() {
    std::string_view text;
    if (!line(text)) return;
    Numbers header(text);
    layout_.numNodeBlocks = header.next<long long>();
    header.next<long long>();
    layout_.minNodeTag = header.next<long long>();
    layout_.maxNodeTag = header.next<long long>();
    if (!header.ok()) return unsupported("a malformed $Nodes section");
    layout_.nodesStart = reader_.offset();
    for (long long b = 0; b < layout_.numNodeBlocks && line(text); ++b) {
      Numbers numbers(text);
      for (int k = 0; k < 3; ++k) numbers.next<int>();
      const long long n = numbers.next<long long>();
      if (!numbers.ok() || n < 0 || !reader_.skip(2 * n)) return unsupported("a malformed $Nodes section");
    }
    skipTo("$EndNodes");
  }

  void elements() {
    std::string_view text;
    if (!line(text)) return;
    Numbers header(text);
    const long long numBlocks = header.next<long long>();
    if (!header.ok()) return unsupported("a malformed $Elements section");
    for (long long b = 0; b < numBlocks && line(text); ++b) {
      Numbers numbers(text);
      ElementBlockHeader block;
      block.dim = numbers.next<int>();
      block.entity = numbers.next<int>();
      block.type = numbers.next<int>();
      block.count = numbers.next<long long>();
      block.firstLine = reader_.offset();
      if (!numbers.ok() || block.count < 0 || !reader_.skip(block.count))
        return unsupported("a malformed $Elements section");
      layout_.elementBlocks.push_back(block);
    }
    skipTo("$EndElements");
  }

  LineReader reader_;
  MshLayout layout_;
};

// The file's physical groups of dimension `dim`: tag -> name ("physical<tag>" when unnamed).
std::map<int, std::string> groupsOf(const MshLayout& layout, int dim) {
  std::map<int, std::string> groups;
  for (const auto& [entity, physicals] : layout.physicalsOf)
    if (entity.first == dim)
      for (int tag : physicals) {
        const auto name = layout.names.find({dim, tag});
        groups[tag] = name != layout.names.end() ? name->second : "physical" + std::to_string(tag);
      }
  return groups;
}

// Name -> tag; false if two groups share a name.
bool namedTags(const std::map<int, std::string>& groups, std::map<std::string, int>& named) {
  for (const auto& [tag, name] : groups)
    if (!named.emplace(name, tag).second) return false;
  return true;
}

int highestDimension(const MshLayout& layout) {
  int dim = -1;
  for (const ElementBlockHeader& block : layout.elementBlocks)
    if (block.count > 0) dim = std::max(dim, block.dim);
  return dim;
}

const std::vector<int>& physicalsOf(const MshLayout& layout, int dim, int entity) {
  static const std::vector<int> none;
  const auto it = layout.physicalsOf.find({dim, entity});
  return it == layout.physicalsOf.end() ? none : it->second;
}

// The blocks of the cells (domain) and of the boundary facets (boundary), with why the reader
// cannot take the file if it cannot.
struct Selection {
  std::string unsupported;
  int dim = 0;
  std::vector<ElementBlockHeader> domain, boundary;
  std::map<std::string, int> boundaryTags, bodyTags;
};

Selection refused(const std::string& why) {
  Selection s;
  s.unsupported = why;
  return s;
}

Selection select(const MshLayout& layout) {
  Selection s;
  s.dim = highestDimension(layout);
  if (s.dim < 2) return refused("it has no elements of dimension 2 or 3");
  if (!layout.hasEntities) return refused("it has no $Entities section");
  const bool bodies = !groupsOf(layout, s.dim).empty();
  if (!namedTags(groupsOf(layout, s.dim), s.bodyTags) || !namedTags(groupsOf(layout, s.dim - 1), s.boundaryTags))
    return refused("two physical groups of one dimension have the same name");
  for (const ElementBlockHeader& block : layout.elementBlocks) {
    const bool grouped = !physicalsOf(layout, block.dim, block.entity).empty();
    if (block.dim == s.dim && (grouped || !bodies)) {
      if (block.type != simplexType(s.dim)) return refused("its cells are not all linear simplices");
      s.domain.push_back(block);
    } else if (block.dim == s.dim - 1 && grouped) {
      if (block.type != simplexType(s.dim - 1)) return refused("its boundary facets are not all linear simplices");
      s.boundary.push_back(block);
    }
  }
  return s;
}

class SliceReader {
 public:
  SliceReader(const std::string& path, const MshLayout& layout, int slice, int numSlices)
      : reader_(path), prefix_("Gmsh mesh file '" + path + "': "), layout_(layout), slice_(slice),
        numSlices_(numSlices) {}

  MshFileSlice read(const Selection& selection) {
    MshFileSlice result;
    result.dim = selection.dim;
    result.boundaryTags = selection.boundaryTags;
    result.bodyTags = selection.bodyTags;
    result.minNodeTag = layout_.minNodeTag;
    result.maxNodeTag = layout_.maxNodeTag;
    readNodes(result);
    readCells(selection, result);
    readFacets(selection, result);
    return result;
  }

 private:
  [[noreturn]] void malformed(const std::string& where) const {
    throw InputError(prefix_ + "a malformed line in its " + where + " section");
  }

  std::string_view line(const char* where) {
    std::string_view text;
    if (!reader_.next(text)) malformed(where);
    return text;
  }

  void readNodes(MshFileSlice& result) {
    reader_.seek(layout_.nodesStart);
    std::vector<long long> tags;
    for (long long b = 0; b < layout_.numNodeBlocks; ++b) {
      Numbers header(line("$Nodes"));
      for (int k = 0; k < 3; ++k) header.next<int>();
      const long long n = header.next<long long>();
      tags.resize(n);
      for (long long& tag : tags) {
        Numbers numbers(line("$Nodes"));
        tag = numbers.next<long long>();
        if (!numbers.ok() || tag < layout_.minNodeTag || tag > layout_.maxNodeTag) malformed("$Nodes");
      }
      for (long long tag : tags) {
        const std::string_view text = line("$Nodes");
        if (MshFileSlice::sliceOfNode(tag, layout_.minNodeTag, layout_.maxNodeTag, numSlices_) != slice_) continue;
        Numbers numbers(text);
        for (int c = 0; c < 3; ++c) result.nodeCoordinates.push_back(numbers.next<double>());
        if (!numbers.ok()) malformed("$Nodes");
        result.nodeTags.push_back(tag);
      }
    }
  }

  // Calls add(block, element tag, node tags) for the elements of index in this slice of those
  // of `blocks`, `nodes` node tags each.
  template <class Add>
  long long readSlice(const std::vector<ElementBlockHeader>& blocks, int nodes, Add add) {
    long long total = 0;
    for (const ElementBlockHeader& block : blocks) total += block.count;
    const long long first = MshFileSlice::sliceStart(total, slice_, numSlices_);
    const long long end = MshFileSlice::sliceStart(total, slice_ + 1, numSlices_);
    long long blockStart = 0;
    long long tags[5];
    for (const ElementBlockHeader& block : blocks) {
      const long long from = std::max(first, blockStart), to = std::min(end, blockStart + block.count);
      if (from < to) {
        reader_.seek(block.firstLine);
        if (!reader_.skip(from - blockStart)) malformed("$Elements");
        for (long long e = from; e < to; ++e) {
          Numbers numbers(line("$Elements"));
          for (int k = 0; k <= nodes; ++k) tags[k] = numbers.next<long long>();
          if (!numbers.ok()) malformed("$Elements");
          add(block, tags[0], tags + 1);
        }
      }
      blockStart += block.count;
    }
    return total;
  }

  void readCells(const Selection& selection, MshFileSlice& result) {
    const int nodes = selection.dim + 1;
    const bool bodies = !selection.bodyTags.empty();
    result.numCells = readSlice(selection.domain, nodes, [&](const ElementBlockHeader& block, long long tag, const long long* n) {
      result.cellElements.push_back(tag);
      result.cellNodes.insert(result.cellNodes.end(), n, n + nodes);
      if (bodies) {  // of several groups, the lowest tag
        const std::vector<int>& physicals = physicalsOf(layout_, block.dim, block.entity);
        result.cellBodies.push_back(*std::min_element(physicals.begin(), physicals.end()));
      }
    });
  }

  void readFacets(const Selection& selection, MshFileSlice& result) {
    const int nodes = selection.dim;
    readSlice(selection.boundary, nodes, [&](const ElementBlockHeader& block, long long tag, const long long* n) {
      const std::vector<int>& physicals = physicalsOf(layout_, block.dim, block.entity);
      for (int group : std::set<int>(physicals.begin(), physicals.end())) {
        result.facetElements.push_back(tag);
        result.facetNodes.insert(result.facetNodes.end(), n, n + nodes);
        result.facetTags.push_back(group);
      }
    });
  }

  LineReader reader_;
  std::string prefix_;
  const MshLayout& layout_;
  int slice_, numSlices_;
};

}  // namespace

long long MshFileSlice::sliceStart(long long total, int slice, int numSlices) {
  return static_cast<long long>(static_cast<__int128>(total) * slice / numSlices);
}

int MshFileSlice::sliceOfNode(long long tag, long long minTag, long long maxTag, int numSlices) {
  const long long chunk = (maxTag - minTag + numSlices) / numSlices;  // ceil((maxTag - minTag + 1) / numSlices)
  return static_cast<int>((tag - minTag) / chunk);
}

MshFileSlice readMshSlice(const std::string& path, int slice, int numSlices, std::string& unsupported) {
  const MshLayout layout = LayoutScanner(path).scan();
  unsupported = layout.unsupported;
  if (!unsupported.empty()) return {};
  const Selection selection = select(layout);
  unsupported = selection.unsupported;
  if (!unsupported.empty()) return {};
  return SliceReader(path, layout, slice, numSlices).read(selection);
}

}  // namespace signorini
