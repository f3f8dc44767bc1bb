// Models through assimp: triangles only, transforms baked in, smooth normals generated where
// missing, diffuse/base colour and its texture per material.
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <new>
#include <set>
#include <sstream>
#include <stdexcept>

#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include "core/util/atomic_file.h"
#include "core/util/colour.h"
#include "core/util/printable.h"
#include "image/image_io.h"
#include "runtime/allocation_budget.h"
#include "runtime/coplanar_draws.h"
#include "runtime/scene.h"

namespace rsaa {
namespace {

bool finite(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Whether any triangle of `scene` has an area (in double: two sides not parallel, relative to
// their lengths, so that the float corners of a sliver far from the origin still count).
bool has_area(const Scene& scene) {
  for (std::size_t t = 0; t + 2 < scene.indices.size(); t += 3) {
    const glm::dvec3 a(scene.vertices[scene.indices[t]].position), b(scene.vertices[scene.indices[t + 1]].position),
        c(scene.vertices[scene.indices[t + 2]].position);
    const glm::dvec3 e1 = b - a, e2 = c - a;
    if (glm::length(glm::cross(e1, e2)) > 1e-12 * glm::length(e1) * glm::length(e2)) return true;
  }
  return false;
}

// Decoded texture in 8-bit sRGB RGBA (straight alpha, as textures are sampled).
TextureImage to_texture(const DecodedImage& d) {
  TextureImage t{d.width, d.height, std::vector<std::uint8_t>(d.rgba.size())};
  for (std::size_t i = 0; i < d.rgba.size(); ++i) {
    const float v = d.rgba[i];
    const bool colour = i % 4 != 3;
    t.rgba[i] = colour && d.float_format
                    ? linear_to_srgb8(v)
                    : static_cast<std::uint8_t>(std::lround(std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f) * 255.0f));
  }
  return t;
}

// What an import may allocate for `input_bytes` of files (docs/reliability.md, Budgets).
std::uint64_t import_budget(std::uint64_t input_bytes) {
  return std::min(kImportBytesFloor + kImportBytesPerInputByte * input_bytes, kImportBytesMax);
}

std::string mib(std::uint64_t bytes) { return std::to_string((bytes + (1u << 19)) >> 20) + " MiB"; }

// Every file assimp opens (the model, and the .mtl, .bin, ... it refers to) must be a regular
// file within the budget: a FIFO or /dev/zero would block or never end. The reason for a refusal
// is kept, since assimp reports only that the file could not be opened.
// Each distinct file opened raises the import's memory budget by its share (kImportBytesPerInputByte).
class BoundedIOSystem : public Assimp::DefaultIOSystem {
 public:
  explicit BoundedIOSystem(AllocationBudget* budget) : budget_(budget) {}
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (std::string(mode).find_first_of("wa+") != std::string::npos) return nullptr;
    try {
      const std::uint64_t size = check_regular_file(file, kMaxModelFileBytes, "model file");
      if (opened_.insert(file).second) input_bytes += size;
      if (budget_) budget_->raise_limit(import_budget(input_bytes) - budget_->limit());
    } catch (const LimitError& e) {
      if (refusal.empty()) refusal = e.what();
      return nullptr;
    } catch (const std::runtime_error&) {
      return nullptr;  // missing: assimp decides whether that matters
    }
    return DefaultIOSystem::Open(file, mode);
  }
  // DefaultIOSystem::Exists opens the file with fopen, which waits forever on a FIFO.
  bool Exists(const char* file) const override {
    struct stat st {};
    return ::stat(file, &st) == 0;
  }
  void end_budget() { budget_ = nullptr; }
  std::string refusal;
  std::uint64_t input_bytes = 0;  // of the distinct files opened

 private:
  AllocationBudget* budget_;
  std::set<std::string> opened_;
};

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace

float generated_normals_crease_degrees(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".ifc" || ext == ".ifczip" ? kBuildingCreaseDegrees : kSmoothCreaseDegrees;
}

namespace {

// Element counts that a header declares, checked against the bytes that could hold them before
// the importer allocates for them (assimp 5.2 trusts them: OutOfMemory.off asks for 24 GB).
// OFF: each vertex takes at least 6 bytes ("0 0 0\n"), each face 8 ("3 0 1 2\n"). PLY: each
// property at least 2 bytes in ASCII, its size in binary.
void check_declared_counts(const std::string& path, const std::string& what, std::uint64_t file_size) {
  const std::string ext = lower_extension(path);
  if (ext != ".off" && ext != ".ply") return;
  std::ifstream in(path, std::ios::binary);
  std::string head(std::size_t(std::min<std::uint64_t>(file_size, 64 * 1024)), '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  const auto too_many = [&](const std::string& element, long double count, long double min_bytes) {
    if (count * min_bytes > (long double)file_size)
      throw std::runtime_error(what + ": declares " + element + " that need at least " +
                               std::to_string((unsigned long long)std::min(count * min_bytes, 1e19L)) +
                               " bytes; the file has " + std::to_string(file_size));
  };
  std::istringstream lines(head);
  std::string line;
  if (ext == ".off") {
    std::vector<long double> counts;
    bool header = false;
    while (counts.size() < 2 && std::getline(lines, line)) {
      line = line.substr(0, line.find('#'));
      std::istringstream words(line);
      std::string word;
      while (counts.size() < 2 && words >> word) {
        if (!header && word.find("OFF") != std::string::npos) {
          header = true;
          continue;
        }
        char* end = nullptr;
        const long double v = std::strtold(word.c_str(), &end);
        if (*end != '\0' || !(v >= 0)) return;  // not a count: the importer reports it
        counts.push_back(v);
      }
    }
    if (counts.size() == 2) {
      too_many(std::to_string((unsigned long long)std::min(counts[0], 1e19L)) + " vertices", counts[0], 6);
      too_many(std::to_string((unsigned long long)std::min(counts[1], 1e19L)) + " faces", counts[1], 8);
    }
    return;
  }
  // PLY
  bool binary = false;
  long double needed = 0, count = 0, per_element = 0;
  std::string element_text;
  const auto size_of = [&](const std::string& type) -> long double {
    if (!binary) return 2;
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "double" || type == "float64") return 8;
    return 4;
  };
  const auto close_element = [&] { needed += count * per_element; };
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "format") {
      std::string kind;
      words >> kind;
      binary = kind.rfind("binary", 0) == 0;
    } else if (key == "element") {
      close_element();
      std::string name, number;
      words >> name >> number;
      char* end = nullptr;
      count = std::strtold(number.c_str(), &end);
      if (*end != '\0' || !(count >= 0)) return;
      per_element = 0;
      element_text = number + " " + name + " elements";
    } else if (key == "property") {
      std::string type;
      words >> type;
      per_element += size_of(type == "list" ? (words >> type, type) : type);
    } else if (key == "end_header") {
      close_element();
      too_many("elements (" + element_text + " and others)", needed, 1);
      return;
    }
  }
  // assimp 5.2 loops forever on a header cut inside a property list (40 s until the loader's
  // time limit): a header must end, with end_header, and headers are small.
  if (head.compare(0, 3, "ply") == 0)
    throw std::runtime_error(what + ": the PLY header has no end_header line" +
                             (file_size > head.size() ? " in its first " + std::to_string(head.size()) + " bytes" : std::string()) +
                             ": the file is cut or not PLY");
}

// What the post-processing steps rely on and importers do not always give: no null node, mesh or
// material, every index in range, arrays present for the counts. Walks the nodes without
// recursion (a chain can be deep) and at most kMaxNodes of them (a cycle would never end).
std::string broken_structure(const aiScene& scene) {
  constexpr std::size_t kMaxNodes = std::size_t{1} << 24;
  if (!scene.mRootNode) return "no root node";
  for (unsigned k = 0; k < scene.mNumMeshes; ++k) {
    const aiMesh* mesh = scene.mMeshes ? scene.mMeshes[k] : nullptr;
    const std::string name = "mesh " + std::to_string(k);
    if (!mesh) return name + " is null";
    if (mesh->mNumVertices > 0 && !mesh->mVertices) return name + " has no vertex array";
    if (mesh->mNumFaces > 0 && !mesh->mFaces) return name + " has no face array";
    if (mesh->mMaterialIndex >= scene.mNumMaterials) return name + " has material " + std::to_string(mesh->mMaterialIndex);
  }
  for (unsigned k = 0; k < scene.mNumMaterials; ++k)
    if (!scene.mMaterials || !scene.mMaterials[k]) return "material " + std::to_string(k) + " is null";
  std::vector<const aiNode*> pending{scene.mRootNode};
  for (std::size_t visited = 0; !pending.empty(); ++visited) {
    if (visited > kMaxNodes) return "more than " + std::to_string(kMaxNodes) + " nodes";
    const aiNode* node = pending.back();
    pending.pop_back();
    const std::string name = "node '" + std::string(node->mName.C_Str()) + "'";
    for (unsigned i = 0; i < node->mNumMeshes; ++i)
      if (!node->mMeshes || node->mMeshes[i] >= scene.mNumMeshes) return name + " refers to a mesh that does not exist";
    for (unsigned i = 0; i < node->mNumChildren; ++i) {
      const aiNode* child = node->mChildren ? node->mChildren[i] : nullptr;
      if (!child) return name + " has a null child";
      pending.push_back(child);
    }
  }
  return "";
}

// rsaa lights and frames scenes itself; a file's lights and cameras are dropped before the
// post-processing, which asserts (aborts the process) on one without a node of its name
// (assimp's own OpenGEX/camera.ogex and collada.ogex).
void drop_lights_and_cameras(aiScene& scene) {
  for (unsigned k = 0; k < scene.mNumLights; ++k) delete scene.mLights[k];
  delete[] scene.mLights;
  scene.mLights = nullptr;
  scene.mNumLights = 0;
  for (unsigned k = 0; k < scene.mNumCameras; ++k) delete scene.mCameras[k];
  delete[] scene.mCameras;
  scene.mCameras = nullptr;
  scene.mNumCameras = 0;
}

glm::vec3 material_albedo(const aiMaterial* material) {
  aiColor4D colour(0.8f, 0.8f, 0.8f, 1.0f);
  if (material->Get(AI_MATKEY_BASE_COLOR, colour) != aiReturn_SUCCESS)
    material->Get(AI_MATKEY_COLOR_DIFFUSE, colour);
  glm::vec3 c(colour.r, colour.g, colour.b);
  for (int k = 0; k < 3; ++k) c[k] = std::isfinite(c[k]) ? std::clamp(c[k], 0.0f, 1.0f) : 0.8f;
  return c;
}

}  // namespace

ImportedModel import_model(const std::string& path, ImportMeasurement* measurement) {
  const std::string what = "model '" + path + "'";
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw std::runtime_error(what + ": file not found");
  std::uint64_t file_size = 0;
  try {
    file_size = check_regular_file(path, kMaxModelFileBytes, "model file");
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(what + ": " + e.what());
  }
  check_declared_counts(path, what, file_size);
  Assimp::Importer importer;
  const aiScene* ai = nullptr;
  BoundedIOSystem* io = nullptr;
  {
    // Only the import is under the budget: what it allocates is what the file declares. The
    // scene it returns is freed with the importer, after the budget has ended.
    AllocationBudget budget(import_budget(0));
    io = new BoundedIOSystem(&budget);
    importer.SetIOHandler(io);  // the importer owns it
    importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, generated_normals_crease_degrees(path));
    try {
      // Post-processing runs only on a scene whose structure holds (broken_structure): an
      // importer that builds a broken one crashed the steps after it (RAW's WithTexture.raw: a
      // node whose children are null segfaulted PreTransformVertices). Not assimp's
      // ValidateDataStructure: it also refuses valid files with an empty mesh.
      ai = importer.ReadFile(path, 0);
      if (ai) {
        const std::string broken = broken_structure(*ai);
        if (!broken.empty()) throw std::runtime_error(what + ": the importer built a broken scene (" + broken + ")");
        drop_lights_and_cameras(const_cast<aiScene&>(*ai));
        ai = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_PreTransformVertices |
                                          aiProcess_GenSmoothNormals | aiProcess_SortByPType |
                                          aiProcess_JoinIdenticalVertices | aiProcess_FindDegenerates);
      }
    } catch (const std::bad_alloc&) {
      if (!budget.refused_request())
        throw std::runtime_error(what + ": out of memory while importing (the sizes it declares do "
                                 "not fit in the memory available)");
    }
    if (measurement) *measurement = {io->input_bytes, budget.peak()};
    // Refused even when the importer went on without what it could not allocate: the scene
    // would be missing parts.
    if (budget.refused_request())
      throw std::runtime_error(
          what + ": importing it would take more memory than its budget of " + mib(budget.limit()) +
          " (" + mib(kImportBytesFloor) + " + " + std::to_string(kImportBytesPerInputByte) +
          " bytes per byte of its " + std::to_string(io->input_bytes) + " bytes of files, at most " +
          mib(kImportBytesMax) + "): the importer asked for " + std::to_string(budget.refused_request()) +
          " bytes with " + mib(std::uint64_t(std::max<std::int64_t>(0, budget.live_when_refused()))) +
          " in use; " +
          (budget.limit() >= kImportBytesMax
               ? std::string("a model this large is beyond the most any model may take to import "
                             "(a binary STL of 1 million triangles fits, one of 3 million does not; "
                             "docs/reliability.md)")
               : std::string("the file declares (or inflates to) more than it holds")));
    io->end_budget();
  }
  // A file the model refers to that was refused (a FIFO, a device, over the budget) refuses
  // the model too, even when the importer would go on without it.
  if (!io->refusal.empty()) throw std::runtime_error(what + ": " + io->refusal);
  if (!ai || !ai->mRootNode) {
    // assimp catches an allocation failure and keeps only its what().
    const std::string error = importer.GetErrorString();
    throw std::runtime_error(what + ": " + (error == std::bad_alloc().what()
                                                ? "out of memory while importing it (an address-space limit, ulimit -v?)"
                                                : error));
  }

  // The copy below allocates per vertex and index: counted first, against the budget.
  std::uint64_t vertex_total = 0, face_total = 0;
  for (unsigned k = 0; k < ai->mNumMeshes; ++k)
    vertex_total += ai->mMeshes[k]->mNumVertices, face_total += ai->mMeshes[k]->mNumFaces;
  if (vertex_total > kMaxSceneVertices || face_total > kMaxSceneTriangles)
    throw std::runtime_error(what + ": " + std::to_string(vertex_total) + " vertices and " +
                             std::to_string(face_total) + " faces; the limit is " +
                             std::to_string(kMaxSceneVertices) + " vertices and " +
                             std::to_string(kMaxSceneTriangles) + " faces");

  ImportedModel model;
  Scene& scene = model.scene;
  scene.name = path;
  std::vector<glm::vec3> albedo_of_material(ai->mNumMaterials, glm::vec3(0.8f));
  model.textures.resize(ai->mNumMaterials);
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  for (unsigned m = 0; m < ai->mNumMaterials; ++m) {
    const aiMaterial* material = ai->mMaterials[m];
    albedo_of_material[m] = material_albedo(material);
    aiString file;
    if (material->GetTexture(aiTextureType_BASE_COLOR, 0, &file) != aiReturn_SUCCESS &&
        material->GetTexture(aiTextureType_DIFFUSE, 0, &file) != aiReturn_SUCCESS)
      continue;
    // An empty name is no texture (MD5's `shader ""`), not the model's directory.
    if (file.length == 0) continue;
    TextureSource& source = model.textures[m];
    if (const aiTexture* embedded = ai->GetEmbeddedTexture(file.C_Str())) {
      if (embedded->mHeight != 0) continue;  // raw texel arrays: not used by the test models
      source.name = path + ": embedded texture " + std::string(file.C_Str());
      source.embedded = true;
      source.bytes.assign(reinterpret_cast<const char*>(embedded->pcData), embedded->mWidth);
      source.format_hint = embedded->achFormatHint;
    } else {
      source.name = (directory / file.C_Str()).string();
    }
  }
  // What the renderer's material id (DrawRange::material, RSAA's material edges) stands for: one
  // appearance, the colour (the material's times the vertex colours, when one colour over the
  // mesh) and the texture it shades with. Meshes that look the same (one material split per mesh,
  // materials differing only in what this renderer does not shade) share an id, so that no false
  // edge runs between them; a mesh whose vertex colours vary is an appearance of its own.
  std::map<std::string, std::uint32_t> appearances;

  std::size_t dropped = 0;  // faces with a non-finite or out-of-range vertex, the first named
  std::string first_dropped;
  for (unsigned k = 0; k < ai->mNumMeshes; ++k) {
    const aiMesh* mesh = ai->mMeshes[k];
    if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    const auto base = static_cast<std::uint32_t>(scene.vertices.size());
    const glm::vec3 albedo = albedo_of_material[mesh->mMaterialIndex];
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      SceneVertex out;
      const aiVector3D& p = mesh->mVertices[v];
      out.position = {p.x, p.y, p.z};
      if (mesh->HasNormals() && finite(mesh->mNormals[v]))
        out.normal = {mesh->mNormals[v].x, mesh->mNormals[v].y, mesh->mNormals[v].z};
      if (mesh->HasTextureCoords(0))
        out.uv = {mesh->mTextureCoords[0][v].x, 1.0f - mesh->mTextureCoords[0][v].y};
      out.albedo = albedo;
      if (mesh->HasVertexColors(0)) {
        // A reflectance, as the material's colour: in [0, 1] (a colour of -5 or 1e38 gave negative
        // or half-float-saturated linear pixels).
        const aiColor4D& c = mesh->mColors[0][v];
        const auto reflectance = [](float x) { return std::isfinite(x) ? std::clamp(x, 0.0f, 1.0f) : 1.0f; };
        out.albedo *= glm::vec3(reflectance(c.r), reflectance(c.g), reflectance(c.b));
      }
      scene.vertices.push_back(out);
    }
    // The material for now: with_textures turns it into the texture's index.
    std::string appearance = model.textures[mesh->mMaterialIndex].name + "|mesh " + std::to_string(k);
    const bool one_colour = std::all_of(scene.vertices.begin() + base, scene.vertices.end(),
                                        [&](const SceneVertex& v) { return v.albedo == scene.vertices[base].albedo; });
    if (one_colour && scene.vertices.size() > base) {
      const glm::vec3 c = scene.vertices[base].albedo;
      char colour[80];
      std::snprintf(colour, sizeof colour, "|%a %a %a", double(c.r), double(c.g), double(c.b));
      appearance = model.textures[mesh->mMaterialIndex].name + colour;
    }
    const std::uint32_t material = appearances.emplace(appearance, std::uint32_t(appearances.size())).first->second;
    DrawRange draw{static_cast<std::uint32_t>(scene.indices.size()), 0, int(mesh->mMaterialIndex), material};
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;
      bool ok = true;
      for (int c = 0; c < 3; ++c)
        ok = ok && face.mIndices[c] < mesh->mNumVertices && finite(mesh->mVertices[face.mIndices[c]]);
      if (!ok) {
        if (dropped++ == 0) first_dropped = "mesh " + std::to_string(k) + " face " + std::to_string(f);
        continue;
      }
      for (int c = 0; c < 3; ++c) scene.indices.push_back(base + face.mIndices[c]);
    }
    draw.index_count = static_cast<std::uint32_t>(scene.indices.size()) - draw.first_index;
    if (draw.index_count > 0) scene.draws.push_back(draw);
  }
  if (scene.indices.empty())
    throw std::runtime_error(what + ": no triangles to draw" +
                             (dropped ? " (" + std::to_string(dropped) +
                                            " had non-finite or out-of-range vertices, the first " + first_dropped + ")"
                                      : ""));
  // A model whose every triangle has zero area draws nothing: refused like one without triangles
  // (an empty image and a table of no masks said nothing was wrong).
  if (!has_area(scene))
    throw std::runtime_error(what + ": no triangles to draw (all " + std::to_string(scene.indices.size() / 3) +
                             " have zero area" +
                             (dropped ? "; " + std::to_string(dropped) + " more had non-finite or out-of-range "
                                        "vertices, the first " + first_dropped
                                      : "") +
                             ")");
  if (dropped)
    std::fprintf(stderr, "rsaa: warning: %s: %zu triangle%s left out: a vertex not finite or out of range (the first %s)\n",
                 printable(what).c_str(), dropped, dropped == 1 ? "" : "s", first_dropped.c_str());
  check_frameable(scene, what);
  return model;
}

Scene with_textures(ImportedModel model) {
  Scene& scene = model.scene;
  const std::string what = "model '" + scene.name + "'";
  std::vector<int> texture_of_material(model.textures.size(), -1);
  std::uint64_t texels = 0;
  std::error_code ec;
  for (std::size_t m = 0; m < model.textures.size(); ++m) {
    const TextureSource& source = model.textures[m];
    if (source.name.empty()) continue;
    // A texture that is missing, a directory or cannot be decoded leaves the material's colour
    // (the geometry is still worth drawing); one that is another kind of file (a FIFO, a device)
    // or over the budget refuses the model, as every other reader does.
    try {
      DecodedImage decoded;
      if (source.embedded) {
        decoded = decode_image("embedded." + source.format_hint, source.bytes, kTextureBudget);
      } else {
        if (!std::filesystem::exists(source.name, ec)) {
          std::fprintf(stderr, "rsaa: warning: %s: texture '%s' not found; drawn in its material's colour\n",
                       printable(what).c_str(), printable(source.name).c_str());
          continue;
        }
        // A name that resolves to a directory (a path that ends in a separator) names no image.
        if (std::filesystem::is_directory(source.name, ec)) {
          std::fprintf(stderr, "rsaa: warning: %s: texture '%s' is a directory; drawn in its material's colour\n",
                       printable(what).c_str(), printable(source.name).c_str());
          continue;
        }
        decoded = decode_image(source.name, read_whole_file(source.name, kTextureBudget.file_bytes, "texture"),
                               kTextureBudget);
      }
      texels += std::uint64_t(decoded.width) * decoded.height;
      if (texels > kMaxSceneTexels)
        throw LimitError(source.name + ": the textures of the model exceed " + std::to_string(kMaxSceneTexels) +
                         " texels in all");
      scene.textures.push_back(to_texture(decoded));
      texture_of_material[m] = int(scene.textures.size()) - 1;
    } catch (const LimitError& e) {
      throw std::runtime_error(what + ": " + e.what());
    } catch (const std::runtime_error& e) {
      std::fprintf(stderr, "rsaa: warning: %s: texture not used (%s); drawn in its material's colour\n",
                   printable(what).c_str(), printable(e.what()).c_str());
    }
  }
  for (DrawRange& draw : scene.draws)
    draw.texture = draw.texture >= 0 && std::size_t(draw.texture) < texture_of_material.size()
                       ? texture_of_material[std::size_t(draw.texture)]
                       : -1;
  rank_coplanar_draws(scene);
  return std::move(model.scene);
}

Scene load_model(const std::string& path, ImportMeasurement* measurement) {
  return with_textures(import_model(path, measurement));
}

}  // namespace rsaa
