#include "kerf/export/mesh_export.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace kerf::exporter {

using converter::Severity;

std::optional<MeshFormat> formatOfPath(std::string_view path) {
  const auto dot = path.rfind('.');
  if (dot == std::string_view::npos) return std::nullopt;
  std::string ext(path.substr(dot + 1));
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == "vtp") return MeshFormat::Vtp;
  if (ext == "stl") return MeshFormat::Stl;
  if (ext == "ply") return MeshFormat::Ply;
  return std::nullopt;
}

SurfaceData surfaceData(const converter::Toolpath& toolpath, std::span<const converter::Diagnostic> findings,
                        const render::SceneOptions& options, bool caps) {
  SurfaceData out;
  out.surface = render::meshCutSurface(toolpath, options, caps);
  std::vector<int> moveFindings(toolpath.moves.size(), 0);
  for (const auto& d : findings) {
    if (!d.move || *d.move >= moveFindings.size()) continue;
    moveFindings[*d.move] |= d.severity == Severity::Error     ? kFindingError
                             : d.severity == Severity::Warning ? kFindingWarning
                                                               : kFindingNote;
  }
  const geometry::Mesh& mesh = out.surface.mesh;
  const std::size_t n = mesh.triangles.size();
  out.cellMove.resize(n);
  out.cellLine.resize(n);
  out.cellSlope.resize(n);
  out.cellFindings.resize(n);
  out.cellPass.assign(n, 0);
  for (std::size_t t = 0; t < n; ++t) {
    const std::uint32_t patch = mesh.trianglePatch[t];
    const auto& tri = mesh.triangles[t];
    out.cellSlope[t] = static_cast<float>(
        static_cast<double>(mesh.vertexSlope[tri[0]] + mesh.vertexSlope[tri[1]] + mesh.vertexSlope[tri[2]]) / 3.0 *
        180.0 / geometry::kPi);
    if (patch == geometry::kCapPatch || patch >= out.surface.patchMove.size()) {
      out.cellMove[t] = -1;
      out.cellLine[t] = 0;
      out.cellFindings[t] = 0;
      out.cellSlope[t] = 0.0f;  // a cap is not swept by the wire
      continue;
    }
    const std::size_t move = out.surface.patchMove[patch];
    out.cellMove[t] = static_cast<int>(move);
    out.cellLine[t] = static_cast<int>(toolpath.moves[move].line);
    out.cellFindings[t] = moveFindings[move];
    if (move < options.movePass.size()) out.cellPass[t] = options.movePass[move];
  }
  return out;
}

std::vector<float> moveDeviations(const converter::DrawingComparison& comparison, std::size_t moves) {
  std::vector<float> out(moves, std::numeric_limits<float>::quiet_NaN());
  for (const converter::EdgeDeviation& e : comparison.edge)
    if (e.move < moves && !(out[e.move] >= static_cast<float>(e.deviation)))
      out[e.move] = static_cast<float>(e.deviation);
  return out;
}

namespace {

vtkNew<vtkPolyData> toPolyData(const SurfaceData& data) {
  const geometry::Mesh& mesh = data.surface.mesh;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.vertices.size()));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), mesh.vertices[i].x(), mesh.vertices[i].y(), mesh.vertices[i].z());
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(static_cast<vtkIdType>(mesh.triangles.size()),
                       static_cast<vtkIdType>(mesh.triangles.size() * 3));
  for (const auto& tri : mesh.triangles) {
    const vtkIdType ids[3] = {tri[0], tri[1], tri[2]};
    polys->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(polys);

  auto intArray = [&](const char* name, const std::vector<int>& values) {
    vtkNew<vtkIntArray> a;
    a->SetName(name);
    a->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i) a->SetValue(static_cast<vtkIdType>(i), values[i]);
    poly->GetCellData()->AddArray(a);
  };
  intArray("move", data.cellMove);
  intArray("line", data.cellLine);
  intArray("findings", data.cellFindings);
  intArray("pass", data.cellPass);
  vtkNew<vtkFloatArray> slope;
  slope->SetName("slope");
  slope->SetNumberOfValues(static_cast<vtkIdType>(data.cellSlope.size()));
  for (std::size_t i = 0; i < data.cellSlope.size(); ++i) slope->SetValue(static_cast<vtkIdType>(i), data.cellSlope[i]);
  poly->GetCellData()->AddArray(slope);
  if (!data.cellDeviation.empty()) {
    vtkNew<vtkFloatArray> deviation;
    deviation->SetName("deviation");
    deviation->SetNumberOfValues(static_cast<vtkIdType>(data.cellDeviation.size()));
    for (std::size_t i = 0; i < data.cellDeviation.size(); ++i)
      deviation->SetValue(static_cast<vtkIdType>(i), data.cellDeviation[i]);
    poly->GetCellData()->AddArray(deviation);
  }
  poly->GetCellData()->SetActiveScalars("slope");
  vtkNew<vtkFloatArray> pointSlope;
  pointSlope->SetName("slope");
  pointSlope->SetNumberOfValues(static_cast<vtkIdType>(mesh.vertexSlope.size()));
  for (std::size_t i = 0; i < mesh.vertexSlope.size(); ++i)
    pointSlope->SetValue(static_cast<vtkIdType>(i),
                         static_cast<float>(static_cast<double>(mesh.vertexSlope[i]) * 180.0 / geometry::kPi));
  poly->GetPointData()->AddArray(pointSlope);
  return poly;
}

}  // namespace

bool writeMesh(const SurfaceData& data, MeshFormat format, const std::string& path, std::string& error) {
  vtkNew<vtkPolyData> poly = toPolyData(data);
  int ok = 0;
  switch (format) {
    case MeshFormat::Vtp: {
      vtkNew<vtkXMLPolyDataWriter> w;
      w->SetInputData(poly);
      w->SetFileName(path.c_str());
      w->SetDataModeToAppended();
      w->SetCompressorTypeToZLib();
      ok = w->Write();
      break;
    }
    case MeshFormat::Stl: {
      vtkNew<vtkSTLWriter> w;
      w->SetInputData(poly);
      w->SetFileName(path.c_str());
      w->SetFileTypeToBinary();
      ok = w->Write();
      break;
    }
    case MeshFormat::Ply: {
      vtkNew<vtkPLYWriter> w;
      w->SetInputData(poly);
      w->SetFileName(path.c_str());
      w->SetFileTypeToBinary();
      ok = w->Write();
      break;
    }
  }
  if (!ok) error = "VTK could not write '" + path + "'";
  return ok != 0;
}

}  // namespace kerf::exporter
