// The results of a sweep (solve/continuation.hpp), stored as columns: one matrix of pair variables and one of
// rates (variables x poses, contiguous, sized once for all the requested inputs), the inputs, and one small
// record per pose (status, iterations, evaluations, rank, residual, condition). A pose whose report says more
// (a limit's location or detail sentence, a singular pose's explanation) keeps its whole SolveReport in a side
// list. Storing a pose therefore copies numbers into place and allocates nothing (a 150,001-pose sweep of
// the paper example holds about 20 MB, not one heap block per vector per pose).
//
//   const SweepResult<double> r = sweep(m, sd, q0, assembly, 0, inputs);
//   for (std::size_t k = 0; k < r.size(); ++k)
//     if (r.has_pose(k)) use(r.input(k), r.q(k), r.qdot(k));  // q(k), qdot(k): column views, no copy
//   for (const SweepPose<double>& p : r.poses) ...               // pose views: p.input, p.q, p.qdot, p.report
#pragma once

#include "rollkin/kinematics.hpp"
#include "rollkin/solve/huge_pages.hpp"
#include "rollkin/solve/report.hpp"

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

namespace rollkin {

/// A read-only view of one column of a variables x poses matrix: pose k's q or qdot.
template <class S> using PoseColumn = Eigen::Block<const MatrixX<S>, Eigen::Dynamic, 1, true>;

/// One pose of a SweepResult, as a view: the input asked for, the pose's variables and rates (views into
/// the result's columns, valid while the result lives) and its report (a copy).
template <class S> struct SweepPose {
  S input;
  PoseColumn<S> q, qdot;  // qdot: rates per unit rate of the swept driver
  SolveReport<S> report;
};

namespace detail {

/// The data of a SweepResult (kept apart so that the poses view can be rebound when a result is copied).
template <class S> struct SweepColumns {
  /// What a pose's report holds beyond the sweep's common fields; `full` >= 0 indexes the side list.
  struct Record {
    S residual = S(0), condition = S(0);
    int iterations = 0, evaluations = 0, rank = 0;
    SolveStatus status = SolveStatus::NotReached;
    std::int32_t full = -1;
  };
  SolveReport<S> assembly;
  std::vector<SolveReport<S>> limits;  // limits met (at most one per direction)
  std::vector<S> inputs_;
  MatrixX<S> q_, qdot_;                // variables x poses
  std::vector<Record> records_;
  std::vector<SolveReport<S>> full_;   // reports that do not fit a Record
  std::size_t links_ = 0;              // link poses kept per pose (0: none kept)
  std::vector<SE2<S>> link_poses_;     // links_ per pose, pose by pose
  std::vector<S> link_angles_;         // the same links' angles in [-pi, pi]
};

}  // namespace detail

template <class S> class SweepResult : public detail::SweepColumns<S> {
  using Base = detail::SweepColumns<S>;
  using Record = typename Base::Record;

 public:
  /// The poses as a range of SweepPose views (built on access): poses[k], poses.size(), range for.
  class Poses {
   public:
    class iterator {
     public:
      using iterator_category = std::input_iterator_tag;
      using value_type = SweepPose<S>;
      using difference_type = std::ptrdiff_t;
      using pointer = void;
      using reference = SweepPose<S>;
      iterator(const SweepResult* r, std::size_t k) : r_(r), k_(k) {}
      SweepPose<S> operator*() const { return r_->pose(k_); }
      iterator& operator++() {
        ++k_;
        return *this;
      }
      bool operator==(const iterator& o) const { return k_ == o.k_; }
      bool operator!=(const iterator& o) const { return k_ != o.k_; }

     private:
      const SweepResult* r_;
      std::size_t k_;
    };
    explicit Poses(const SweepResult* r) : r_(r) {}
    std::size_t size() const { return r_->size(); }
    bool empty() const { return size() == 0; }
    SweepPose<S> operator[](std::size_t k) const { return r_->pose(k); }
    SweepPose<S> front() const { return r_->pose(0); }
    SweepPose<S> back() const { return r_->pose(size() - 1); }
    iterator begin() const { return {r_, 0}; }
    iterator end() const { return {r_, size()}; }

   private:
    const SweepResult* r_;
  };
  Poses poses{this};  // one per requested input, in the requested order
  /// Keeps every pose's values and rates: each requested input is solved (continuation.hpp).
  static constexpr bool holds_values = true;

  SweepResult() = default;
  SweepResult(const SweepResult& o) : Base(o) {}
  SweepResult(SweepResult&& o) noexcept : Base(std::move(o)) {}
  SweepResult& operator=(const SweepResult& o) {
    Base::operator=(o);
    return *this;
  }
  SweepResult& operator=(SweepResult&& o) noexcept {
    Base::operator=(std::move(o));
    return *this;
  }

  /// Room for `inputs.size()` poses of `variables` variables, each with status `status` and no values yet
  /// (their columns are unwritten until set_pose() or zero_columns_without_values()), and for the world
  /// poses of `links` links per pose (0: none kept; ContinuationSettings::link_poses).
  SweepResult(const SolveReport<S>& assembly, const std::vector<S>& inputs, Eigen::Index variables, SolveStatus status,
              std::size_t links = 0) {
    const auto n = static_cast<Eigen::Index>(inputs.size());
    this->assembly = assembly;
    this->inputs_ = inputs;
    // Allocated and advised for huge pages (huge_pages.hpp), not written here: set_pose() writes each column
    // once and zero_columns_without_values() the rest, so the memory is touched once.
    for (MatrixX<S>* m : {&this->q_, &this->qdot_}) {
      m->resize(variables, n);
      advise_huge_pages(m->data(), static_cast<std::size_t>(m->size()) * sizeof(S));
    }
    Record blank;
    blank.status = status;
    this->records_.reserve(inputs.size());
    advise_huge_pages(this->records_.data(), inputs.size() * sizeof(Record));
    this->records_.assign(inputs.size(), blank);
    this->links_ = links;
    this->link_poses_.resize(links * inputs.size());
    this->link_angles_.resize(links * inputs.size());
  }

  std::size_t size() const { return this->records_.size(); }
  const S& input(std::size_t k) const { return this->inputs_[k]; }
  PoseColumn<S> q(std::size_t k) const { return this->q_.col(static_cast<Eigen::Index>(k)); }
  PoseColumn<S> qdot(std::size_t k) const { return this->qdot_.col(static_cast<Eigen::Index>(k)); }
  /// All poses' variables (variables x poses) and rates; columns of poses without values are zero.
  const MatrixX<S>& q_columns() const { return this->q_; }
  const MatrixX<S>& qdot_columns() const { return this->qdot_; }
  SolveStatus status(std::size_t k) const { return this->records_[k].status; }
  bool ok(std::size_t k) const { return status(k) == SolveStatus::Converged; }
  bool has_pose(std::size_t k) const { return ok(k) || status(k) == SolveStatus::Singular; }

  /// Pose k's report (a copy; the common fields equations and unknowns come from the assembly's).
  SolveReport<S> report(std::size_t k) const {
    const Record& r = this->records_[k];
    if (r.full >= 0) return this->full_[static_cast<std::size_t>(r.full)];
    SolveReport<S> rep;
    rep.status = r.status;
    rep.iterations = r.iterations;
    rep.evaluations = r.evaluations;
    rep.residual = r.residual;
    rep.condition = r.condition;
    rep.rank = r.rank;
    rep.equations = this->assembly.equations;
    rep.unknowns = this->assembly.unknowns;
    return rep;
  }

  /// Pose k's residual (its report's, without copying the report).
  const S& residual(std::size_t k) const {
    const Record& r = this->records_[k];
    return r.full >= 0 ? this->full_[static_cast<std::size_t>(r.full)].residual : r.residual;
  }
  SweepPose<S> pose(std::size_t k) const { return SweepPose<S>{input(k), q(k), qdot(k), report(k)}; }

  /// Whether the result keeps every pose's link poses (ContinuationSettings::link_poses).
  bool keeps_link_poses() const { return this->links_ > 0; }
  /// The world pose of every link at pose k (Mechanism::links order) when kept and the pose has values,
  /// else nullptr.
  const SE2<S>* link_poses(std::size_t k) const {
    return keeps_link_poses() && has_pose(k) ? this->link_poses_.data() + k * this->links_ : nullptr;
  }
  /// Their angles in [-pi, pi] (link_poses_near), else nullptr.
  const S* link_angles(std::size_t k) const {
    return keeps_link_poses() && has_pose(k) ? this->link_angles_.data() + k * this->links_ : nullptr;
  }
  /// Stores pose k's link poses and angles at its values q from the pair states in d (link_poses_near: no
  /// pair evaluated again where d was evaluated within a closing step of q).
  void set_link_poses(std::size_t k, const Mechanism<S>& m, const KinematicsData<S>& d, const VectorX<S>& q) {
    link_poses_near(m, d, q, this->link_poses_.data() + k * this->links_, this->link_angles_.data() + k * this->links_);
  }

  /// Stores pose k: its values, rates and report (no allocation unless the report carries a detail).
  template <class Q, class V> void set_pose(std::size_t k, const Q& q, const V& qdot, const SolveReport<S>& rep) {
    this->q_.col(static_cast<Eigen::Index>(k)) = q;
    this->qdot_.col(static_cast<Eigen::Index>(k)) = qdot;
    set_report(k, rep);
  }

  /// Stores pose k's report.
  void set_report(std::size_t k, const SolveReport<S>& rep) {
    Record& r = this->records_[k];
    r.status = rep.status;
    r.iterations = rep.iterations;
    r.evaluations = rep.evaluations;
    r.rank = rep.rank;
    r.residual = rep.residual;
    r.condition = rep.condition;
    r.full = -1;
    if (fits_record(rep, this->assembly)) return;
    r.full = static_cast<std::int32_t>(this->full_.size());
    this->full_.push_back(rep);
  }

  /// Zeroes the columns of the poses that hold no values (the constructor leaves the columns unwritten);
  /// sweep() calls it last.
  void zero_columns_without_values() {
    for (std::size_t k = 0; k < size(); ++k)
      if (!has_pose(k)) {
        this->q_.col(static_cast<Eigen::Index>(k)).setZero();
        this->qdot_.col(static_cast<Eigen::Index>(k)).setZero();
      }
  }

  /// Gives pose k the report already stored for pose `like` (no copy of a long report).
  void share_report(std::size_t k, std::size_t like) { this->records_[k] = this->records_[like]; }
  /// A limit the continuation met (limits).
  void add_limit(const SolveReport<S>& limit) { this->limits.push_back(limit); }

  /// Every requested pose plainly solved (no limit, no singular pose).
  bool all_solved() const {
    for (const Record& r : this->records_)
      if (r.status != SolveStatus::Converged) return false;
    return this->assembly.ok();
  }

  /// Whether a pose's report is told by a Record alone (no detail, no limit, the assembly's sizes), so that
  /// only the reports that say more are kept whole.
  static bool fits_record(const SolveReport<S>& rep, const SolveReport<S>& assembly) {
    return rep.detail.empty() && rep.limit_input == S(0) && rep.pair < 0 && rep.contour < 0 && rep.corner < 0 &&
           rep.equations == assembly.equations && rep.unknowns == assembly.unknowns;
  }
};

}  // namespace rollkin
