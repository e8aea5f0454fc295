class_name DemoPlants
extends RefCounted
## The plants of the demo's "Plants" map: the Sapling test plants (res://test_plants, made by
## Blender's Sapling Tree Gen: assets/test_plants/make_test_plants.py) made into FieldPlants from
## their scenes, their impostors baked on first use into user://demo_plants and loaded from there
## afterwards, under a name that changes with the scene file and the addon's baker (a changed plant
## or bake is baked again). Map symbols: 't' maple, 'b' bottlebrush bush, 'g' grass clump.

## Map symbol → test plant scene.
const SCENES: Dictionary = {
	"t": "res://test_plants/maple_tree.glb",
	"b": "res://test_plants/bottlebrush_bush.glb",
	"g": "res://test_plants/grass_clump.glb",
}
const FOLDER: String = "user://demo_plants"
## Their leaves' flutter in the wind ([member SunflowerPlant.flutter]).
const FLUTTER: float = 0.2
const ImpostorBaker: GDScript = preload("res://addons/sunflower_field/plant/impostor_baker.gd")
const PLANT_SURFACE_PATH: String = "res://addons/sunflower_field/shaders/plant_surface.gdshaderinc"


## The legend entries of the test plants, baked under [param host] (a node in the tree that draws);
## await it. An entry is left out, with an error naming the scene, when it cannot be made.
static func legend(host: Node) -> Dictionary:
	var entries: Dictionary = {}
	for symbol: String in SCENES:
		var scene: PackedScene = load(SCENES[symbol]) as PackedScene
		var plant: SunflowerPlant = SunflowerPlant.from_scene(scene) if scene else null
		if plant == null:
			push_error("demo: cannot make a plant of %s" % SCENES[symbol])
			continue
		plant.flutter = FLUTTER
		# The maple's impostor shadows are as dark as its meshes', their specks elsewhere
		# (docs/plants.md): its near plants cast from their meshes' own specks.
		plant.impostor_shadows = symbol != "t"
		var baked_name: String = "%s_%s" % [plant.name, _fingerprint(SCENES[symbol])]
		if not _load_baked(plant, baked_name):
			_forget_bakes(plant.name)
			if await plant.bake_impostors(host, FOLDER, baked_name) != OK:
				push_error("demo: the impostors of %s were not baked" % SCENES[symbol])
		entries[symbol] = plant
	return entries


## What the bake of [param scene_path] depends on, as a short code: the scene file's and the addon's
## baker's (its light passes and views' measures included) and plant material's contents.
static func _fingerprint(scene_path: String) -> String:
	var sources: String = ""
	for path: String in [
		scene_path,
		ImpostorBaker.resource_path,
		ImpostorBaker.BakeLight.resource_path,
		ImpostorBaker.BakeLight.PlantMaterial.resource_path,
		ImpostorBaker.ViewsMeasure.resource_path,
		PLANT_SURFACE_PATH
	]:
		sources += FileAccess.get_md5(path)
	return sources.md5_text().left(12)


## Removes the atlases earlier runs baked for the plant [param plant_name] (of an older scene or baker).
static func _forget_bakes(plant_name: String) -> void:
	if not DirAccess.dir_exists_absolute(FOLDER):
		return
	for file: String in DirAccess.get_files_at(FOLDER):
		if file.begins_with(plant_name + "_") and file.ends_with(".png"):
			DirAccess.remove_absolute(FOLDER.path_join(file))


## Gives [param plant] the atlases an earlier run baked for it as [param baked_name] (the test plants
## give off no light; a back-light atlas when one was baked), and what the bake measures on its
## views (their alpha cuts and where the plant is thin); false when there are none.
static func _load_baked(plant: SunflowerPlant, baked_name: String) -> bool:
	var kinds: PackedStringArray = SunflowerPlant.IMPOSTOR_TEXTURES.duplicate()
	kinds.append(SunflowerPlant.BACKLIGHT_TEXTURE)
	for kind: String in kinds:
		var path: String = FOLDER.path_join("%s_%s.png" % [baked_name, kind])
		var image: Image = Image.load_from_file(path) if FileAccess.file_exists(path) else null
		if image == null:
			if kind in SunflowerPlant.IMPOSTOR_TEXTURES:
				return false
			continue
		if kind == "views":
			ImpostorBaker.ViewsMeasure.measure(plant, image)  # before the texture premultiplies it
		plant.set("impostor_" + kind, ImpostorBaker.atlas_texture(image, plant.name))
	return true
