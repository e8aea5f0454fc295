// The library's entry point: loads the binding, registers the library's classes and their docs.
#include "binding/class_binder.h"
#include "binding/rendering_server.h"
#include "sunflower_changes.h"
#include "sunflower_drawing.h"
#include "sunflower_map.h"
#include "sunflower_parameters.h"
#include "sunflower_placement.h"
#include "sunflower_simulation.h"

#include "doc_data.gen.h"

#include <cstring>

namespace {

bool registered = false;

void initialize(void *, GDExtensionInitializationLevel p_level) {
	if (p_level == GDEXTENSION_INITIALIZATION_SCENE) {
		// The RenderingServer singleton is not published yet at this level: it is looked up on first use.
		gdx::register_class<SunflowerSimulation>("RefCounted");
		gdx::register_class<SunflowerDrawing>("RefCounted");
		gdx::register_class<SunflowerChanges>("RefCounted");
		gdx::register_class<SunflowerParameters>("RefCounted");
		gdx::register_class<SunflowerPlacement>("RefCounted");
		gdx::register_class<SunflowerMap>("RefCounted");
		registered = true;
	} else if (p_level == GDEXTENSION_INITIALIZATION_EDITOR && registered) {
		for (const char *xml : sunflower_doc::XML) {
			gdx::api.editor_help_load_xml_from_utf8_chars_and_len(xml, static_cast<GDExtensionInt>(std::strlen(xml)));
		}
	}
}

void deinitialize(void *, GDExtensionInitializationLevel p_level) {
	if (p_level == GDEXTENSION_INITIALIZATION_SCENE) {
		gdx::unregister_classes();
		gdx::RenderingServer::unload();
		gdx::release_api();
		registered = false;
	}
}

} // namespace

// The entry point is the library's only exported symbol (Windows: dllexport; elsewhere hidden
// visibility by default plus the linker's export list, gdextension/exports.map on Linux).
#ifdef _WIN32
#define SUNFLOWER_EXPORT __declspec(dllexport)
#else
#define SUNFLOWER_EXPORT __attribute__((visibility("default")))
#endif

extern "C" {

SUNFLOWER_EXPORT GDExtensionBool sunflower_library_init(GDExtensionInterfaceGetProcAddress p_get_proc_address,
		GDExtensionClassLibraryPtr p_library, GDExtensionInitialization *r_initialization) {
	if (!gdx::load_api(p_get_proc_address, p_library)) {
		return false;
	}
	r_initialization->initialize = &initialize;
	r_initialization->deinitialize = &deinitialize;
	r_initialization->userdata = nullptr;
	r_initialization->minimum_initialization_level = GDEXTENSION_INITIALIZATION_SCENE;
	return true;
}
}
