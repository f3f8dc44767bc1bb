// Models through assimp: triangles only, transforms baked in, smooth normals generated where
// missing, diffuse/base colour and its texture per material.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "core/colour.h"
#include "runtime/scene.h"

namespace rsaa {
namespace {

bool finite(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Decodes an image file or an in-memory (embedded) image into 8-bit RGBA.
TextureImage read_texture(const std::string& name, const void* data = nullptr, std::size_t size = 0) {
  OIIO::Filesystem::IOMemReader memory(data, size);
  std::unique_ptr<OIIO::ImageInput> in =
      OIIO::ImageInput::open(name, nullptr, data ? &memory : nullptr);
  if (!in) throw std::runtime_error("cannot read texture " + name + " (" + OIIO::geterror() + ")");
  const OIIO::ImageSpec& spec = in->spec();
  TextureImage t{spec.width, spec.height, {}};
  std::vector<std::uint8_t> raw(std::size_t(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, raw.data()))
    throw std::runtime_error("cannot decode texture " + name);
  t.rgba.resize(std::size_t(spec.width) * spec.height * 4);
  for (std::size_t i = 0; i < std::size_t(spec.width) * spec.height; ++i)
    for (int c = 0; c < 4; ++c)
      t.rgba[4 * i + c] = c < spec.nchannels ? raw[i * spec.nchannels + c]
                          : c == 3           ? 255
                                             : raw[i * spec.nchannels];
  return t;
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

Scene load_model(const std::string& path) {
  const std::string what = "model '" + path + "'";
  if (!std::filesystem::exists(path)) throw std::runtime_error(what + ": file not found");
  if (std::filesystem::is_directory(path)) throw std::runtime_error(what + ": is a directory");
  Assimp::Importer importer;
  const aiScene* ai = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_GenSmoothNormals |
                aiProcess_SortByPType | aiProcess_JoinIdenticalVertices | aiProcess_FindDegenerates);
  if (!ai || !ai->mRootNode) throw std::runtime_error(what + ": " + importer.GetErrorString());

  Scene scene;
  scene.name = path;
  std::vector<int> texture_of_material(ai->mNumMaterials, -1);
  std::vector<glm::vec3> albedo_of_material(ai->mNumMaterials, glm::vec3(0.8f));
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  for (unsigned m = 0; m < ai->mNumMaterials; ++m) {
    const aiMaterial* material = ai->mMaterials[m];
    albedo_of_material[m] = material_albedo(material);
    aiString file;
    if (material->GetTexture(aiTextureType_BASE_COLOR, 0, &file) != aiReturn_SUCCESS &&
        material->GetTexture(aiTextureType_DIFFUSE, 0, &file) != aiReturn_SUCCESS)
      continue;
    try {
      if (const aiTexture* embedded = ai->GetEmbeddedTexture(file.C_Str())) {
        if (embedded->mHeight != 0) continue;  // raw texel arrays: not used by the test models
        const std::string hint = std::string("embedded.") + embedded->achFormatHint;
        scene.textures.push_back(read_texture(hint, embedded->pcData, embedded->mWidth));
      } else {
        scene.textures.push_back(read_texture((directory / file.C_Str()).string()));
      }
      texture_of_material[m] = int(scene.textures.size()) - 1;
    } catch (const std::exception&) {
      // A missing texture leaves the material's colour; the geometry is still worth drawing.
    }
  }

  std::size_t dropped = 0;
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
        const aiColor4D& c = mesh->mColors[0][v];
        out.albedo *= glm::vec3(std::isfinite(c.r) ? c.r : 1, std::isfinite(c.g) ? c.g : 1,
                                std::isfinite(c.b) ? c.b : 1);
      }
      scene.vertices.push_back(out);
    }
    DrawRange draw{static_cast<std::uint32_t>(scene.indices.size()), 0,
                   texture_of_material[mesh->mMaterialIndex]};
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;
      bool ok = true;
      for (int c = 0; c < 3; ++c)
        ok = ok && face.mIndices[c] < mesh->mNumVertices && finite(mesh->mVertices[face.mIndices[c]]);
      if (!ok) {
        ++dropped;
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
                                            " had non-finite or out-of-range vertices)"
                                      : ""));
  const glm::vec3 extent = scene.bounds_max() - scene.bounds_min();
  if (!(std::isfinite(extent.x) && std::isfinite(extent.y) && std::isfinite(extent.z)))
    throw std::runtime_error(what + ": vertex positions overflow");
  return scene;
}

}  // namespace rsaa
