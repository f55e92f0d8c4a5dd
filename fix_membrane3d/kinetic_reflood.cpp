// The local update of the kinetic flood's flood (kinetic_exterior.h: why it is exact).
#include "kinetic_exterior.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace membrane3d {

namespace kinetic {

namespace {

// The round-off allowance of a link's test, as kinetic_exterior.cpp's.
constexpr double kLinkRoundOff = 1e-9;

// The links followed grow with the cells reached anew; beyond this many times those of
// the last whole flood, the whole flood is run (and they are recorded anew).
constexpr std::size_t kLinkGrowth = 3;

} // namespace

bool Exterior::alive(const Tracked &x) const
{
  return t_.tds().cells().is_used(x.first) && x.first->info().serial == x.second;
}

unsigned Exterior::find(unsigned a)
{
  auto it = klass_.find(a);
  if (it == klass_.end()) return a;
  const unsigned root = find(it->second);
  it->second = root;
  return root;
}

void Exterior::unite(unsigned a, unsigned b)
{
  a = find(a);
  b = find(b);
  if (a != b) klass_[a] = b;
}

// The edges whose status (linked or not) changed since it was read; their entries take
// the present status (and a slack from here).
std::vector<std::pair<int, int>> Exterior::changed_links()
{
  std::vector<double> moved(now_.size());
  for (std::size_t i = 0; i < now_.size(); ++i) moved[i] = (now_[i].x - anchor_[i]).norm();
  std::vector<std::pair<int, int>> out;
  for (Link &l : links_) {
    if (moved[l.a] + moved[l.b] < l.slack) continue;
    const Sphere &p = now_[l.a], &q = now_[l.b];
    // the expression of the flood's test, to the last bit
    const double distance = (p.x - q.x).norm(), gap = distance - p.r - q.r;
    const double t = threshold(l.a, l.b);
    const bool linked = gap <= t;
    if (linked == l.linked) continue;
    out.emplace_back(l.a, l.b);
    l.linked = linked;
    l.slack = std::abs(gap - t) - kLinkRoundOff * (distance + t) - moved[l.a] - moved[l.b];
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// The facets on the changed edges: a reached cell's way through one that became a wall
// is cut (`orphan`), a dry cell across one from a reached cell is looked at (`recheck`).
void Exterior::changed_facets(const std::vector<std::pair<int, int>> &edges,
                              std::vector<Cell> &orphan, std::vector<Cell> &recheck)
{
  for (const auto &e : edges) {
    const Vertex a = vertex_[e.first], b = vertex_[e.second];
    if (a == Vertex() || b == Vertex()) continue;
    Cell c;
    int i, j;
    if (!t_.is_edge(a, b, c, i, j)) continue;
    auto start = t_.incident_cells(c, i, j), x = start;
    do {
      const Cell cell = x;
      const int ia = cell->index(a), ib = cell->index(b);
      for (int k = 0; k < 4; ++k) {
        if (k == ia || k == ib) continue;
        const Cell n = cell->neighbor(k);
        const CellState &s = cell->info(), &m = n->info();
        if (s.wet < 0 || m.wet < 0) continue; // made: flooded again anyway
        if (s.wet == 1 && m.wet == 1) {
          if (!wall(cell, k)) continue;
          if (s.parent == k) orphan.push_back(cell);
          if (m.parent == n->index(cell)) orphan.push_back(n);
        } else if (s.wet == 1 || m.wet == 1) {
          recheck.push_back(s.wet == 1 ? n : cell);
        }
      }
    } while (++x != start);
  }
}

// c is reached through its facet `through` (4: from outside).
void Exterior::reach(Cell c, int through, std::vector<Cell> &front, std::vector<Cell> &reached)
{
  CellState &s = c->info();
  if (s.wet == 0 && s.group >= 0) { // an old dry cell: removed from its group
    if (!all_sealed(c)) ++removed_[s.group];
    for (int k = 0; k < 4; ++k) {
      const Cell n = c->neighbor(k);
      if (n->info().wet != 0 || n->info().group < 0) continue;
      unite(s.serial, n->info().serial);
      dry_next_.emplace_back(n, n->info().serial);
    }
  }
  s.wet = 1;
  s.parent = static_cast<signed char>(through);
  s.group = -1;
  front.push_back(c);
  reached.push_back(c);
}

int Exterior::fragment_root(int f)
{
  while (fragments_[f].parent != f) f = fragments_[f].parent = fragments_[fragments_[f].parent].parent;
  return f;
}

// No class with two fragments growing, no growing fragment without an old dry cell.
bool Exterior::race_done()
{
  std::unordered_map<unsigned, int> growing; // class root -> its growing fragment root
  std::vector<char> active(fragments_.size(), 0);
  for (std::size_t f = 0; f < fragments_.size(); ++f)
    if (fragments_[f].head < fragments_[f].queue.size()) active[fragment_root(static_cast<int>(f))] = 1;
  for (std::size_t f = 0; f < fragments_.size(); ++f) {
    if (!active[f]) continue;
    if (!fragments_[f].old) return false;
    const unsigned k = find(static_cast<unsigned>(fragments_[f].klass));
    const auto it = growing.find(k);
    if (it != growing.end() && it->second != static_cast<int>(f)) return false;
    growing[k] = static_cast<int>(f);
  }
  return true;
}

// The dry cells connected to `from` that are not yet of group `label`: to it.
void Exterior::relabel(const std::vector<Cell> &from, int label, std::vector<Cell> &changed)
{
  std::vector<Cell> front;
  for (const Cell c : from)
    if (c->info().wet == 0 && c->info().group != label) {
      c->info().group = label;
      front.push_back(c);
    }
  for (std::size_t head = 0; head < front.size(); ++head) {
    const Cell c = front[head];
    changed.push_back(c);
    for (int k = 0; k < 4; ++k) {
      const Cell n = c->neighbor(k);
      if (n->info().wet != 0 || n->info().group == label) continue;
      n->info().group = label;
      front.push_back(n);
    }
  }
  visited_ += static_cast<long>(front.size());
}

bool Exterior::update(const std::vector<int> &touched, Boundary &out)
{
  if (!local_ || links_.size() > kLinkGrowth * links_recorded_ + 1000) return false;
  // the made cells (every cell made by an insertion or removal is around the hole's or
  // the inserted sphere's vertex)
  std::vector<Cell> made, around;
  for (int i : touched) {
    if (vertex_[i] == Vertex()) continue;
    around.clear();
    t_.incident_cells(vertex_[i], std::back_inserter(around));
    for (const Cell c : around)
      if (c->info().serial == 0) {
        c->info().serial = ++serial_;
        c->info().wet = -2;
        c->info().group = -1;
        made.push_back(c);
      }
  }
  // (1) reached
  std::vector<Cell> roots, recheck;
  changed_facets(changed_links(), roots, recheck);
  for (const Tracked &x : orphan_roots_)
    if (alive(x) && x.first->info().wet == 1) roots.push_back(x.first);
  std::vector<Cell> orphans;
  for (const Cell r : roots) {
    if (r->info().wet != 1) continue;
    r->info().wet = 2;
    orphans.push_back(r);
  }
  for (std::size_t head = 0; head < orphans.size(); ++head) {
    const Cell c = orphans[head];
    for (int k = 0; k < 4; ++k) {
      const Cell n = c->neighbor(k);
      CellState &m = n->info();
      if (m.wet != 1 || m.parent < 0 || m.parent > 3 || n->neighbor(m.parent) != c) continue;
      m.wet = 2;
      orphans.push_back(n);
    }
  }
  std::vector<Cell> front, reached;
  auto seed = [&](Cell c) {
    if (c->info().wet == 1 || all_sealed(c)) return;
    if (t_.is_infinite(c)) return reach(c, 4, front, reached);
    for (int k = 0; k < 4; ++k)
      if (c->neighbor(k)->info().wet == 1 && !wall(c, k)) return reach(c, k, front, reached);
  };
  for (const Cell c : orphans) seed(c);
  for (const Cell c : made) seed(c);
  for (const Cell c : recheck)
    if (c->info().wet == 0) seed(c);
  for (std::size_t head = 0; head < front.size(); ++head) {
    const Cell c = front[head];
    for (int k = 0; k < 4; ++k) {
      const Cell n = c->neighbor(k);
      if (n->info().wet == 1 || all_sealed(n) || wall(c, k)) continue;
      reach(n, n->index(c), front, reached);
    }
  }
  visited_ += static_cast<long>(orphans.size() + made.size() + reached.size());
  // (2) dry groups: the new dry cells
  std::vector<Cell> fresh;
  for (const Cell c : orphans)
    if (c->info().wet == 2) fresh.push_back(c);
  for (const Cell c : made)
    if (c->info().wet == -2) fresh.push_back(c);
  for (const Cell c : fresh) {
    c->info().wet = 0;
    c->info().group = -1;
  }
  fragments_.clear();
  unsigned klass = 0; // the new dry cells' classes: after every serial
  auto start = [&](Cell c, int k) {
    CellState &s = c->info();
    if (s.stamp == step_) return;
    s.stamp = step_;
    const int f = static_cast<int>(fragments_.size());
    s.fragment = f;
    fragments_.push_back({{c}, {c}, 0, f, k, s.group >= 0});
  };
  for (const Cell c : fresh) start(c, static_cast<int>(serial_ + ++klass));
  for (const Tracked &x : dry_next_)
    if (alive(x) && x.first->info().wet == 0 && x.first->info().group >= 0)
      start(x.first, static_cast<int>(find(x.second)));
  while (!race_done()) {
    for (std::size_t f = 0; f < fragments_.size(); ++f) {
      Fragment &g = fragments_[f];
      if (g.head == g.queue.size()) continue;
      const Cell c = g.queue[g.head++];
      for (int k = 0; k < 4; ++k) {
        const Cell n = c->neighbor(k);
        CellState &m = n->info();
        if (m.wet != 0) continue;
        if (m.stamp == step_) { // met another fragment: merged, with their classes
          const int a = fragment_root(static_cast<int>(f)), b = fragment_root(m.fragment);
          if (a == b) continue;
          fragments_[a].parent = b;
          fragments_[b].old = fragments_[b].old || fragments_[a].old;
          unite(static_cast<unsigned>(fragments_[a].klass), static_cast<unsigned>(fragments_[b].klass));
          continue;
        }
        m.stamp = step_;
        m.fragment = static_cast<int>(f);
        fragments_[f].queue.push_back(n);
        fragments_[f].cells.push_back(n);
        if (m.group >= 0) {
          const int r = fragment_root(static_cast<int>(f));
          fragments_[r].old = true;
        }
      }
    }
  }
  // the groups: finished fragments (whole), growing ones with the old groups they touch
  std::vector<char> growing(fragments_.size(), 0);
  for (std::size_t f = 0; f < fragments_.size(); ++f)
    if (fragments_[f].head < fragments_[f].queue.size()) growing[fragment_root(static_cast<int>(f))] = 1;
  std::unordered_map<int, long> finished_size, in_finished; // by root; by old group
  std::unordered_map<int, long> fresh_size;                  // by growing root
  std::unordered_map<int, int> group_of_root;                // growing root -> an old group
  std::unordered_map<int, int> merged; // old group -> another of its component (union-find)
  std::function<int(int)> top = [&](int g) {
    auto it = merged.find(g);
    if (it == merged.end()) return g;
    return it->second = top(it->second);
  };
  for (std::size_t f = 0; f < fragments_.size(); ++f) {
    const int r = fragment_root(static_cast<int>(f));
    for (const Cell c : fragments_[f].cells) {
      const CellState &s = c->info();
      const long unsealed = all_sealed(c) ? 0 : 1;
      if (!growing[r]) {
        finished_size[r] += unsealed;
        if (s.group >= 0) in_finished[s.group] += unsealed;
      } else if (s.group < 0) {
        fresh_size[r] += unsealed;
      } else {
        auto it = group_of_root.find(r);
        if (it == group_of_root.end()) {
          group_of_root[r] = s.group;
        } else if (top(it->second) != top(s.group)) {
          merged[top(s.group)] = top(it->second);
        }
      }
    }
    visited_ += static_cast<long>(fragments_[f].cells.size());
  }
  std::unordered_map<int, long> component; // by top old group: its count
  auto left = [&](int g) {
    const auto r = removed_.find(g), e = in_finished.find(g);
    return size_[g] - (r == removed_.end() ? 0 : r->second) - (e == in_finished.end() ? 0 : e->second);
  };
  std::set<int> touched_groups;
  for (const auto &x : group_of_root) touched_groups.insert(x.second);
  for (const auto &x : merged) touched_groups.insert(x.first), touched_groups.insert(x.second);
  for (const int g : touched_groups) component[top(g)] += left(g);
  for (const auto &x : fresh_size) component[top(group_of_root.at(x.first))] += x.second;
  // the sample: the continuation of the last one, larger than any other group
  const int kept = kept_group_;
  if (kept < 0 || kept >= static_cast<int>(size_.size())) return false;
  const bool kept_touched = touched_groups.count(kept) > 0;
  const long kept_count = kept_touched ? component[top(kept)] : left(kept);
  long other = 0;
  for (const auto &x : component)
    if (!kept_touched || x.first != top(kept)) other = std::max(other, x.second);
  for (const auto &x : finished_size) other = std::max(other, x.second);
  for (std::size_t g = 0; g < size_.size(); ++g)
    if (static_cast<int>(g) != kept && !touched_groups.count(static_cast<int>(g)))
      other = std::max(other, left(static_cast<int>(g)));
  if (!(kept_count > other)) return false;
  // relabel: the sample's component, the other growing components, the finished ones
  std::vector<Cell> changed = made;
  changed.insert(changed.end(), orphans.begin(), orphans.end());
  changed.insert(changed.end(), reached.begin(), reached.end());
  std::unordered_map<int, std::vector<Cell>> seeds; // by top old group
  for (std::size_t f = 0; f < fragments_.size(); ++f) {
    const int r = fragment_root(static_cast<int>(f));
    if (!growing[r]) continue;
    auto &to = seeds[top(group_of_root.at(r))];
    to.insert(to.end(), fragments_[f].cells.begin(), fragments_[f].cells.end());
  }
  for (const auto &x : removed_) size_[x.first] = left(x.first);
  for (const auto &x : in_finished) size_[x.first] = left(x.first);
  // finished fragments: a label per root
  std::unordered_map<int, int> label_of_root;
  for (std::size_t f = 0; f < fragments_.size(); ++f) {
    const int r = fragment_root(static_cast<int>(f));
    if (growing[r]) continue;
    auto it = label_of_root.find(r);
    if (it == label_of_root.end()) {
      it = label_of_root.emplace(r, static_cast<int>(size_.size())).first;
      size_.push_back(finished_size[r]);
    }
    for (const Cell c : fragments_[f].cells) {
      c->info().group = it->second;
      changed.push_back(c);
    }
  }
  for (const int g : touched_groups) size_[g] = 0;
  for (auto &x : seeds) {
    const int label = kept_touched && x.first == top(kept) ? kept : static_cast<int>(size_.size());
    if (label != kept) size_.push_back(0);
    size_[label] = component[x.first];
    relabel(x.second, label, changed);
  }
  if (!kept_touched) size_[kept] = kept_count;
  // (3) the membrane and the sides
  for (const Cell c : changed) {
    CellState &s = c->info();
    s.flooded = s.wet == 1 || s.group != kept;
  }
  for (const Cell c : changed)
    for (int k = 0; k < 4; ++k) erase_facet(c, k);
  std::vector<int> spheres(touched);
  for (const Cell c : changed)
    for (int k = 0; k < 4; ++k) {
      const Vertex v = c->vertex(k);
      if (finite(v)) spheres.push_back(v->info());
      const Cell n = c->neighbor(k);
      if (n->info().flooded == c->info().flooded || ignored_facet(c, k)) continue;
      auto f = c->info().flooded ? outward_facet(n, n->index(c)) : outward_facet(c, k);
      std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
      facets_.insert(f);
    }
  for (const Cell c : reached) add_links(c);
  out.facets.assign(facets_.begin(), facets_.end());
  std::sort(spheres.begin(), spheres.end());
  spheres.erase(std::unique(spheres.begin(), spheres.end()), spheres.end());
  for (int i : spheres) out.side[i] = side_of(i);
  for (std::size_t i = 0; i < now_.size(); ++i)
    if (vertex_[i] == Vertex()) out.side[i] = side_of(static_cast<int>(i));
  return true;
}

} // namespace kinetic

} // namespace membrane3d
