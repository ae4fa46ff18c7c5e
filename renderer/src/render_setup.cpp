#include <brdfnav/renderer/render_setup.h>

namespace brdfnav {

EnvMap load_env(const RenderSetup& setup) {
  return EnvMap::load(setup.env, EnvLoadOptions{setup.sanitize_env});
}

Scene load_scene(const RenderSetup& setup) {
  return Scene::load(setup.scene);
}

}  // namespace brdfnav
