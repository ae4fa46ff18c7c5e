// What a render is made from, named as a user names it: the map's file, whether its NaN/Inf
// texels are zeroed, the resolution and the scene. The CLI's --env, --sanitize-env, --res and
// --scene fill one (app/command_options.h); the rest of a render is the renderer's.
#pragma once

#include <brdfnav/renderer/env_map.h>
#include <brdfnav/renderer/scene.h>

#include <string>

namespace brdfnav {

struct RenderSetup {
  std::string env = kDefaultEnvPath;
  bool sanitize_env = false;
  int resolution = 320;
  std::string scene = "sphere";
};

// The setup's map (EnvMap::load with its sanitize option) and scene (Scene::load): EnvMapError
// and SceneError name the file.
EnvMap load_env(const RenderSetup& setup);
Scene load_scene(const RenderSetup& setup);

}  // namespace brdfnav
