#include <cmp/mesh/EditableMesh.h>

namespace cmp
{

Status EditableMesh::build(const TriangleMesh& mesh)
{
  CornerTable table;
  if (!table.build(mesh))
    return Status::error("the surface is not a closed, oriented, edge-manifold mesh");
  points_ = mesh.points;
  triangles_ = mesh.triangles;
  opposite_.resize(table.halfedgeCount());
  for (int h = 0; h < table.halfedgeCount(); ++h)
    opposite_[h] = table.opposite(h);
  outgoing_.resize(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    outgoing_[v] = table.outgoing(v);
    if (outgoing_[v] < 0)
      return Status::error("point " + std::to_string(v) + " belongs to no triangle");
  }
  tags_.assign(opposite_.size(), -1);
  origins_.assign(points_.size(), VertexOrigin{});
  inputTriangle_.resize(triangles_.size());
  for (int t = 0; t < triangleCount(); ++t)
    inputTriangle_[t] = t;
  return {};
}

int EditableMesh::findHalfedge(int a, int b) const
{
  const int start = outgoing_[a];
  int h = start;
  do
  {
    if (to(h) == b)
      return h;
    h = nextAroundVertex(h);
  } while (h != start);
  return -1;
}

int EditableMesh::splitEdge(int h, double t)
{
  // Before: t1 = (a, b, c) holds h = a->b, t2 = (b, a, d) holds g = b->a.
  // After:  t1 = (a, m, c), t3 = (m, b, c), t2 = (b, m, d), t4 = (m, a, d).
  const int g = opposite_[h];
  const int t1 = triangleOf(h), t2 = triangleOf(g);
  const int a = from(h), b = to(h);
  const int bc = next(h), ad = next(g); // these indices become m->c and m->d
  const int outerBC = opposite_[bc], outerAD = opposite_[ad];
  const int tagAB = tags_[h], tagBA = tags_[g], tagBC = tags_[bc], tagAD = tags_[ad];
  const int c = to(bc), d = to(ad);

  const int m = vertexCount();
  points_.push_back((1.0 - t) * points_[a] + t * points_[b]);
  origins_.push_back({ a, b, t });
  triangles_[t1][h % 3 == 2 ? 0 : h % 3 + 1] = m;
  triangles_[t2][g % 3 == 2 ? 0 : g % 3 + 1] = m;
  const int t3 = triangleCount(), t4 = t3 + 1;
  triangles_.push_back({ m, b, c });
  triangles_.push_back({ m, a, d });
  inputTriangle_.push_back(inputTriangle_[t1]);
  inputTriangle_.push_back(inputTriangle_[t2]);
  opposite_.resize(3 * (t4 + 1), -1);
  tags_.resize(opposite_.size(), -1);

  const int mb = 3 * t3, bcNew = 3 * t3 + 1, cm = 3 * t3 + 2;
  const int ma = 3 * t4, adNew = 3 * t4 + 1, dm = 3 * t4 + 2;
  link(h, ma);     // a->m | m->a
  link(g, mb);     // b->m | m->b
  link(bc, cm);    // m->c | c->m
  link(ad, dm);    // m->d | d->m
  link(bcNew, outerBC);
  link(adNew, outerAD);

  tags_[h] = tags_[mb] = tagAB; // a->m and m->b continue a->b
  tags_[g] = tags_[ma] = tagBA; // b->m and m->a continue b->a
  tags_[bcNew] = tagBC;
  tags_[adNew] = tagAD;
  tags_[bc] = tags_[cm] = tags_[ad] = tags_[dm] = -1;

  outgoing_.push_back(mb);
  outgoing_[a] = h;
  outgoing_[b] = bcNew;
  outgoing_[c] = cm;
  outgoing_[d] = dm;
  return m;
}

void EditableMesh::collapseEdge(int h)
{
  // t1 = (v, x, a) holds h = v->x, t2 = (x, v, b) holds g = x->v. Afterwards
  // every triangle of v uses x, and the outer edges of t1 and t2 are glued.
  const int g = opposite_[h];
  const int v = from(h), x = to(h);
  const int xa = next(h), av = prev(h), vb = next(g), bx = prev(g);
  const int a = to(xa), b = to(vb);
  const int outerXA = opposite_[xa], outerAV = opposite_[av], outerVB = opposite_[vb], outerBX = opposite_[bx];

  for (int around = nextAroundVertex(h); around != h; around = nextAroundVertex(around))
    triangles_[around / 3][around % 3] = x;
  // v->a becomes x->a beside a->x; b->v becomes b->x beside x->b.
  link(outerXA, outerAV);
  link(outerVB, outerBX);
  tags_[outerAV] = tags_[xa];
  tags_[outerVB] = tags_[bx];
  outgoing_[x] = outerAV;
  outgoing_[a] = outerXA;
  outgoing_[b] = outerVB;
  outgoing_[v] = -1;
  for (int t : { triangleOf(h), triangleOf(g) })
  {
    triangles_[t] = { -1, -1, -1 };
    for (int k = 0; k < 3; ++k)
    {
      opposite_[3 * t + k] = -1;
      tags_[3 * t + k] = -1;
    }
  }
}

TriangleMesh EditableMesh::toTriangleMesh() const
{
  TriangleMesh mesh;
  mesh.points = points_;
  mesh.triangles.reserve(triangles_.size());
  for (const Triangle& tri : triangles_)
    if (tri[0] >= 0)
      mesh.triangles.push_back(tri);
  return mesh;
}

} // namespace cmp
