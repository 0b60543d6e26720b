// The selected DXF entities chained end to end into one contour (dxf_detail.hpp).
#include "dxf_detail.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace rollkin::dxf {
namespace {

// ---- chaining ------------------------------------------------------------------------------------------------



class Chainer {
 public:
  Chainer(std::string file, const std::vector<Piece>& pieces) : file_(std::move(file)), pieces_(pieces) {
    V lo = pieces[0].segments[0].points[0], hi = lo;
    for (const Piece& p : pieces)
      for (const Segment& s : p.segments)
        for (const V& q : s.points) {
          lo = lo.cwiseMin(q);
          hi = hi.cwiseMax(q);
        }
    size_ = (hi - lo).norm();
    tol_ = kDxfJoinTolerance * size_;
    for (const Piece& p : pieces)
      for (const Segment& s : p.segments) {
        double reach = 0;
        for (const V& q : s.points) reach = std::max(reach, (q - s.points.front()).norm());
        if (!(reach > tol_))
          fail(p.label + " has a piece at " + point_text(s.points.front()) + " no longer than the join tolerance (" +
               tolerance_text() + "): nearly repeated vertices or a vanishing arc");
      }
  }

  double size() const { return size_; }

  Chain chain() {
    Chain c;
    for (std::size_t k = 0; k < pieces_.size(); ++k) {
      const Piece& p = pieces_[k];
      if (p.closed && pieces_.size() > 1)
        fail(p.label + " is closed on its own but is not the only entity selected (" + std::to_string(pieces_.size()) +
             " are); a contour is one chain: select it alone (by handle) or move the others to another layer");
      const V s = p.segments.front().points.front(), e = p.segments.back().points.back();
      if (k == 0) {
        append(c, k, false);
        joints_.push_back({s, "the chain's start (the start of " + p.label + ")"});
      } else {
        const V end = c.segments.back().points.back();
        if (c.closed) leftover(c, k);
        if ((s - end).norm() <= tol_) append(c, k, false);
        else if ((e - end).norm() <= tol_) append(c, k, true);
        else not_at_end(c, k, end);
      }
      const V end = c.segments.back().points.back();
      const V start = c.segments.front().points.front();
      if ((end - start).norm() <= tol_) {
        c.segments.back().points.back() = start;
        c.closed = true;
      }
    }
    if (pieces_.size() == 1 && pieces_[0].closed && !c.closed)
      fail(pieces_[0].label + " is flagged closed but ends at " + point_text(c.segments.back().points.back()) +
           ", not at its start " + point_text(c.segments.front().points.front()) +
           " (for a periodic SPLINE, rollkin needs the wrapped control points)");
    return c;
  }

 private:
  struct Joint {
    V point;
    std::string what;
  };

  [[noreturn]] void fail(const std::string& message) const { throw InputError(file_, "", message); }

  std::string tolerance_text() const {
    return "tolerance " + number(tol_) + " = " + number(kDxfJoinTolerance) + " x drawing size " + number(size_);
  }

  void append(Chain& c, std::size_t k, bool reverse) {
    const Piece& p = pieces_[k];
    const std::size_t first = c.segments.size();
    if (!reverse) {
      for (const Segment& s : p.segments) c.segments.push_back(s);
    } else {
      for (auto it = p.segments.rbegin(); it != p.segments.rend(); ++it) c.segments.push_back(reversed(*it));
    }
    c.owner.resize(c.segments.size(), k);
    if (first > 0) {
      c.segments[first].points.front() = c.segments[first - 1].points.back();  // snap the joint
      joints_.push_back({c.segments[first].points.front(), "where " + pieces_[c.owner[first - 1]].label + " and " + p.label + " meet"});
    }
  }

  /// Entity k meets neither end... of the chain's end: a branch if it touches the chain elsewhere, else a gap.
  [[noreturn]] void not_at_end(const Chain& c, std::size_t k, const V& end) const {
    const Piece& p = pieces_[k];
    const V s = p.segments.front().points.front(), e = p.segments.back().points.back();
    for (const Joint& j : joints_)
      for (const V& q : {s, e})
        if ((q - j.point).norm() <= tol_)
          fail(p.label + " meets the chain at " + point_text(q) + ", " + j.what + ", not at the chain's end " + point_text(end) +
               " (the end of " + pieces_[c.owner.back()].label + "): a branch or an entity out of order; a contour is one "
               "chain, its entities listed in order along it");
    const bool start_nearer = (s - end).norm() <= (e - end).norm();
    const V near = start_nearer ? s : e;
    fail("gap of " + number((near - end).norm()) + " between the end of " + pieces_[c.owner.back()].label + " at " +
         point_text(end) + " and " + p.label + " (its nearer end at " + point_text(near) + "); " + tolerance_text() +
         "; entities are chained end to end in file order");
  }

  [[noreturn]] void leftover(const Chain& c, std::size_t k) const {
    const Piece& p = pieces_[k];
    fail("the chain closed at " + point_text(c.segments.front().points.front()) + " with " + pieces_[c.owner.back()].label +
         ", but " + p.label + " follows (a branch, or a second contour on the layer); a contour is one chain");
  }

  std::string file_;
  const std::vector<Piece>& pieces_;
  std::vector<Joint> joints_;
  double size_ = 0, tol_ = 0;
};

}  // namespace

Chain chain_pieces(const std::string& file, const std::vector<Piece>& pieces, double& size) {
  Chainer chainer(file, pieces);
  size = chainer.size();
  return chainer.chain();
}

}  // namespace rollkin::dxf
