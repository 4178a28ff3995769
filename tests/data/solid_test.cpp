// kerf export --caps as a solid for CAD, judged by VTK's feature-edge filter on the STL the program
// writes: no edge of three or more faces (a lead-in standing on the part as a fin of no thickness
// made them: 4 on sector_r40, 47 on circle_under_square) and no open edge.
#include <gtest/gtest.h>

#include <vtkFeatureEdges.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

struct Edges {
  vtkIdType nonManifold = -1, boundary = -1, triangles = -1;
};

Edges edgesOf(const std::string& stl) {
  vtkNew<vtkSTLReader> reader;  // merges coincident points, as a CAD import does
  reader->SetFileName(stl.c_str());
  reader->Update();
  Edges e;
  e.triangles = reader->GetOutput()->GetNumberOfPolys();
  for (const bool nonManifold : {true, false}) {
    vtkNew<vtkFeatureEdges> edges;
    edges->SetInputConnection(reader->GetOutputPort());
    edges->FeatureEdgesOff();
    edges->ManifoldEdgesOff();
    edges->NonManifoldEdgesOff();
    edges->BoundaryEdgesOff();
    if (nonManifold)
      edges->NonManifoldEdgesOn();
    else
      edges->BoundaryEdgesOn();
    edges->Update();
    (nonManifold ? e.nonManifold : e.boundary) = edges->GetOutput()->GetNumberOfLines();
  }
  return e;
}

class solid_test : public testing::TestWithParam<const char*> {};

TEST_P(solid_test, caps_make_a_closed_manifold_solid_without_the_lead_paths) {
  const std::filesystem::path work = std::filesystem::path(KERF_SOLID_WORK);
  std::filesystem::create_directories(work);
  const std::string name = GetParam();
  const std::string stl = (work / (name + ".stl")).string();
  const std::string command = "'" + std::string(KERF_PROGRAM) + "' export '" + KERF_SAMPLES + "/" + name +
                              ".nc' --caps -o '" + stl + "' 2> '" + (work / (name + ".log")).string() + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const Edges e = edgesOf(stl);
  EXPECT_GT(e.triangles, 100);
  EXPECT_EQ(e.nonManifold, 0) << name << ": edges of three or more faces";
  EXPECT_EQ(e.boundary, 0) << name << ": open edges";
}

// Not taper_punch_2deg: its upper contour does not close where the lower does (the taper's seam,
// K0609), so no cap closes it yet (docs/rendering.md).
INSTANTIATE_TEST_SUITE_P(samples, solid_test, testing::Values("sector_r40", "circle_under_square"));

}  // namespace
