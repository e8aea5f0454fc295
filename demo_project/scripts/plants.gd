class_name DemoPlants
extends RefCounted
## The plants of the demo's "Plants" map: the Sapling test plants (res://test_plants, made by
## Blender's Sapling Tree Gen: assets/test_plants/make_test_plants.py) made into FieldPlants from
## their scenes, their impostors baked on first use into user://demo_plants and loaded from there
## afterwards. Map symbols: 't' maple, 'b' bottlebrush bush, 'g' grass clump.

## Map symbol → test plant scene.
const SCENES: Dictionary = {
	"t": "res://test_plants/maple_tree.glb",
	"b": "res://test_plants/bottlebrush_bush.glb",
	"g": "res://test_plants/grass_clump.glb",
}
const FOLDER: String = "user://demo_plants"
## Their leaves' flutter in the wind ([member FieldPlant.flutter]).
const FLUTTER: float = 0.2
const ImpostorBaker: GDScript = preload("res://addons/sunflower_field/impostor_baker.gd")


## The legend entries of the test plants, baked under [param host] (a node in the tree that draws);
## await it. An entry is left out, with an error naming the scene, when it cannot be made.
static func legend(host: Node) -> Dictionary:
	var entries: Dictionary = {}
	for symbol: String in SCENES:
		var scene: PackedScene = load(SCENES[symbol]) as PackedScene
		var plant: FieldPlant = FieldPlant.from_scene(scene) if scene else null
		if plant == null:
			push_error("demo: cannot make a plant of %s" % SCENES[symbol])
			continue
		plant.flutter = FLUTTER
		# The maple's impostor shadows are lighter than its branches' (docs/plants.md): its near
		# plants cast from their meshes.
		plant.impostor_shadows = symbol != "t"
		if not _load_baked(plant) and await plant.bake_impostors(host, FOLDER, plant.name) != OK:
			push_error("demo: the impostors of %s were not baked" % SCENES[symbol])
		entries[symbol] = plant
	return entries


## Gives [param plant] the atlases an earlier run baked for it; false when there are none.
static func _load_baked(plant: FieldPlant) -> bool:
	for kind: String in FieldPlant.IMPOSTOR_TEXTURES:
		var path: String = FOLDER.path_join("%s_%s.png" % [plant.name, kind])
		var image: Image = Image.load_from_file(path) if FileAccess.file_exists(path) else null
		if image == null:
			return false
		plant.set("impostor_" + kind, ImpostorBaker.atlas_texture(image, plant.name))
	return true
