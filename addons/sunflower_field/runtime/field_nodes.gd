@tool
extends RefCounted
## The internal nodes that draw one field (one native simulation): per far tile (8 × 8 chunks of one
## species, or a merged tile of a level above covering 2 × 2 tiles below) one static
## MultiMeshInstance3D of its plants' impostors (sprite and billboard draw the same multi-view
## impostor, so one GPU copy of a far plant serves both; its visibility range begins where the
## shader gives all its plants its level or a higher one and ends at the field's draw distance, and
## its visibility parent, its parent tile's node, hides it where that one is drawn: the engine draws
## a cut through the tree of tiles, each place once; the plants fade from level to level one after
## another by their own distance, whichever tile draws them), the dynamic bucket nodes of
## the near plants, and the scenes the legend places; and per species the active-chunk mask that
## keeps the tiles from drawing the plants the near buckets draw. The only script that makes
## MultiMeshes or sets visibility ranges. Tile nodes can be made a few at a time, hidden, and shown
## at once. (The cells' textures the impostors read are cell_textures.gd's; how far the sun's shadows
## reach, sun_reach.gd's.)

const Native: GDScript = preload("../native/native.gd")
const NativeField: GDScript = preload("../native/native_field.gd")
const ImpostorSet: GDScript = preload("impostor_set.gd")
const FarTileTable: GDScript = preload("far_tile_table.gd")
const PartMeshes: GDScript = preload("../plant/part_meshes.gd")
const CellTextures: GDScript = preload("cell_textures.gd")
const SunReach: GDScript = preload("sun_reach.gd")
const LegendScenes: GDScript = preload("legend_scenes.gd")
## The name of the child of each impostor node that draws its shadows.
const CASTER_NAME: String = "ShadowCaster"
## The parts of a plant, bottom to top, as node names use them.
const PART_NAMES: PackedStringArray = PartMeshes.PART_NAMES

var simulation: NativeField
## The simulation's far tiles, read when the first tile node is made.
var tiles: FarTileTable
## Near plants drawn at mesh level 1 or 2 cast their shadows from their level-3 mesh (set before
## [method finish]; see SunflowerField.cheap_shadows).
var cheap_shadows: bool = true
## Per species: near plants drawn at this mesh level (0–2) or coarser cast no shadows from their
## meshes, their tile's impostor casts for them (see SunflowerField.impostor_shadows_from and
## SunflowerPlant.impostor_shadows); 3, or no entry: every mesh level casts. Set by
## [method set_impostor_shadows_from].
var impostor_shadows_from: PackedInt32Array = []
## Tile nodes made, and taken over from the previous field, by this field's build.
var tiles_made: int = 0
var tiles_kept: int = 0
var _owner: Node3D
var _impostors: Array[ImpostorSet]  # per species
var _tile_nodes: Array[MultiMeshInstance3D] = []
var _dynamic_nodes: Array[MultiMeshInstance3D] = []
var _dynamic_buckets: PackedInt32Array = []  # the native bucket each dynamic node draws
var _shown_buckets: PackedByteArray = []  # the filled buckets the nodes' visibility follows
var _object_nodes: Array[Node] = []
var _mesh_nodes: Array[MultiMeshInstance3D] = []  # the near mesh levels' nodes, and each one's level
var _mesh_node_levels: PackedInt32Array = []
var _mesh_node_species: PackedInt32Array = []
var _whole: Array[bool] = []  # per species: its near plants drawn whole (one node per level)
var _cell_textures: CellTextures
var _cell_size: float = 0.0
## The field drawn before this one: tiles that draw the same here take its nodes and GPU buffers.
var _previous: RefCounted
var _previous_by_key: Dictionary = {}  # tile key → the previous field's tile
var _shadow_reach: float = -1.0  # what the tiles' shadows follow (see follow_sun; −1: not looked up yet)
var _sun: SunReach


## Nodes of [param owner] for [param field_simulation], its far levels drawn with [param impostors]
## (an ImpostorSet per species).
func _init(owner: Node3D, field_simulation: NativeField, impostors: Array[ImpostorSet]) -> void:
	_owner = owner
	simulation = field_simulation
	_impostors = impostors
	_cell_textures = CellTextures.new(field_simulation, impostors)
	_sun = SunReach.new(owner)


## Builds on [param previous] (the FieldNodes drawn now, or null): a tile that lies where one of
## its tiles lies and draws the same (equal key and signature) takes that tile's node and buffer
## instead of new ones, so a small change of a large map (a paint stroke, say) makes nodes and
## uploads buffers only for the tiles it touched.
func reuse(previous: RefCounted) -> void:
	_previous = previous
	if previous == null:
		return
	var old_tiles: FarTileTable = previous.tile_table()
	for tile: int in old_tiles.count:
		_previous_by_key[old_tiles.key(tile)] = tile


## The simulation's far tiles ([member tiles]), read from it on the first call.
func tile_table() -> FarTileTable:
	if tiles == null:
		tiles = FarTileTable.new(simulation)
	return tiles


## Makes hidden tile nodes (or takes the previous field's, see [method reuse]) until all exist or
## the next would overrun [param budget_usec] (negative: no limit; one node is always made); true
## when every tile has its node.
func make_tiles(budget_usec: int, max_draw_distance: float) -> bool:
	var start: int = Time.get_ticks_usec()
	var tile_count: int = tile_table().count
	var slowest: int = 0  # the longest a node took in this step, to stop before the budget is overrun
	while _tile_nodes.size() < tile_count:
		var node_start: int = Time.get_ticks_usec()
		var tile: int = _tile_nodes.size()
		if _take_previous(tile, max_draw_distance):
			if budget_usec >= 0 and Time.get_ticks_usec() - start + slowest >= budget_usec:
				break
			continue
		tiles_made += 1
		var aabb: AABB = tiles.aabb(tile)
		var impostors: ImpostorSet = _impostors[tiles.species(tile)]
		var node: MultiMeshInstance3D = _make_node(_tile_node_name(tile), impostors.mesh(true), aabb)
		_add_caster(node, impostors.caster(true))
		node.visible = false  # shown when the whole field is ready
		_tile_nodes.append(node)
		_set_level(node, tile)
		_set_range(tile, max_draw_distance)
		simulation.set_tile_multimesh(tile, node.multimesh.get_rid())
		var now: int = Time.get_ticks_usec()
		slowest = maxi(slowest, now - node_start)
		if budget_usec >= 0 and now - start + slowest >= budget_usec:
			break
	return _tile_nodes.size() >= tile_count


## Takes the previous field's node for [param tile] when it draws the same; true if it did.
func _take_previous(tile: int, max_draw_distance: float) -> bool:
	var old: int = _previous_by_key.get(tiles.key(tile), -1)
	if old < 0 or _previous.tile_table().signature(old) != tiles.signature(tile):
		return false
	var node: MultiMeshInstance3D = _previous.give_tile_node(old)
	if node == null:
		return false
	_tile_nodes.append(node)
	simulation.adopt_tile_multimesh(tile, node.multimesh.get_rid())
	_set_level(node, tile)  # the merge distance may have changed
	_set_range(tile, max_draw_distance)
	tiles_kept += 1
	return true


## [param tile]'s place among the merged levels, for the impostor shader, which picks the plants
## its level draws from the observer; and where its level begins.
func _set_level(node: MultiMeshInstance3D, tile: int) -> void:
	for drawn: GeometryInstance3D in [node, _caster_of(node)]:
		drawn.set_instance_shader_parameter(&"tile_merge", tiles.merge(tile))
		drawn.visibility_range_begin = tiles.shown_from(tile)
	_set_shadow(node, tile)


## Hides each tile (and its shadow caster) where its parent tile is drawn (the parent's visibility
## range begins where all its plants are given to its level or a higher one), once every tile has
## its node; a tile's node taken from the previous field gets its new parent.
func _link_parents() -> void:
	for tile: int in _tile_nodes.size():
		var parent: int = tiles.parent(tile)
		var node: MultiMeshInstance3D = _tile_nodes[tile]
		for drawn: GeometryInstance3D in [node, _caster_of(node)]:
			drawn.visibility_parent = drawn.get_path_to(_tile_nodes[parent]) if parent >= 0 else NodePath()


## A merged level's plants are at least its begin distance away (200 m by default): beyond the sun's
## shadows its tiles cast none, which keeps them out of every shadow pass their boxes reach into.
func _set_shadow(node: MultiMeshInstance3D, tile: int) -> void:
	if _shadow_reach < 0.0:
		_shadow_reach = _sun.reach()
	_caster_of(node).visible = tiles.begin(tile) < _shadow_reach


## Keeps the tiles' shadows as far as the sun's when a sun's shadows change (its distance, turned on
## or off, hidden, added or removed; in a running game or in the editor). Once a frame: it reads a
## few properties of the suns it knows, and looks for suns again only when the scene tree gained or
## lost a DirectionalLight3D.
func follow_sun() -> void:
	var reach: float = _sun.reach()
	if reach == _shadow_reach:
		return
	_shadow_reach = reach
	for tile: int in _tile_nodes.size():
		if _tile_nodes[tile]:
			_set_shadow(_tile_nodes[tile], tile)


## Hands [param tile]'s node to a field built on this one (and forgets it); null when it has none
## (any more).
func give_tile_node(tile: int) -> MultiMeshInstance3D:
	if tile >= _tile_nodes.size() or not is_instance_valid(_tile_nodes[tile]):
		return null
	var node: MultiMeshInstance3D = _tile_nodes[tile]
	_tile_nodes[tile] = null
	return node


## The share of tile nodes made, 0 to 1.
func get_tile_progress() -> float:
	return _tile_nodes.size() / maxf(tile_table().count, 1.0)


## Completes the field: the near plants' bucket nodes and the legend's scenes, then shows it all.
## [param species_plants] holds each species' SunflowerPlant: a plant drawn whole gets one node per
## level ([code]Mesh1[/code]…), any other one per level and part ([code]Mesh1Bottom[/code]…). The
## near plants' bounds reach [param sway_margin] metres past the chunks' (a swaying plant's lean).
func finish(species_plants: Array, legend: Dictionary, cell_size: float, sway_margin: float) -> void:
	_cell_size = cell_size
	var aabb: AABB = _field_aabb().grow(sway_margin)
	var per_species: int = Native.constant(&"BUCKET_COUNT")
	for species: int in simulation.get_species_count():
		var prefix: String = "" if species == 0 else "Plant%d" % species
		var plant: Resource = species_plants[species]
		var first: int = species * per_species
		_whole.append(plant.drawn_whole())
		var levels: int = Native.constant(&"MESH_LEVEL_COUNT")
		for level: int in levels:
			if _whole[species]:
				var whole: MultiMeshInstance3D = _make_node(
					"%sMesh%d" % [prefix, level + 1], plant.whole_mesh(level), aabb
				)
				var whole_bucket: int = first + Native.mesh_bucket(level, 0)
				_add_dynamic(whole, whole_bucket)
				_mesh_nodes.append(whole)
				_mesh_node_levels.append(level)
				_mesh_node_species.append(species)
				if cheap_shadows and level < levels - 1:
					_add_shadow_twin(whole, whole_bucket, plant.whole_mesh(levels - 1))
				_give_instance_parameters(whole, plant)
				continue
			for part: int in PART_NAMES.size():
				var node_name: String = "%sMesh%d%s" % [prefix, level + 1, PART_NAMES[part].capitalize()]
				var node: MultiMeshInstance3D = _make_node(node_name, plant.mesh_for_field(level, part), aabb)
				var bucket: int = first + Native.mesh_bucket(level, part)
				_add_dynamic(node, bucket)
				_mesh_nodes.append(node)
				_mesh_node_levels.append(level)
				_mesh_node_species.append(species)
				if cheap_shadows and level < levels - 1:
					_add_shadow_twin(node, bucket, plant.mesh_for_field(levels - 1, part))
				_give_instance_parameters(node, plant)
		# The near sprites and billboards: one multi-view impostor draws both.
		var impostors: MultiMeshInstance3D = _make_node(prefix + "Impostors", _impostors[species].mesh(), aabb)
		_add_dynamic(impostors, first + Native.constant(&"BUCKET_IMPOSTOR"))
		_add_caster(impostors, _impostors[species].caster())
	set_impostor_shadows_from(impostor_shadows_from)
	_object_nodes.append_array(LegendScenes.place(_owner, simulation, legend, cell_size))
	for tile: int in _tile_nodes.size():
		var node: MultiMeshInstance3D = _tile_nodes[tile]
		node.visible = true
		# Tile nodes are named after the tile's key (where it lies); one made while the old field's
		# node of that key was still there had a generated name until now.
		if str(node.name).begins_with("@"):
			node.name = _tile_node_name(tile)
	_link_parents()
	_previous = null  # its remaining nodes go with it


## Tells the tiles which chunks the near buckets draw now (after the simulation's update): one mask
## texture per species, a byte per chunk cell, given to that species' impostor material; and hides
## the tiles whose chunks are all drawn near (an instance the shader skips still costs a draw call).
func update_masks() -> void:
	if not _cell_textures.masks_changed():
		return
	var drawn: PackedByteArray = simulation.get_tiles_drawn()
	# A tile whose chunks are all drawn near is hidden, unless its caster casts for near plants.
	for tile: int in mini(_tile_nodes.size(), drawn.size()):
		if _tile_nodes[tile]:
			_tile_nodes[tile].visible = drawn[tile] != 0 or _casts_from(tile_table().species(tile)) < PartMeshes.LEVELS
	_cell_textures.update_masks()


## Hides the impostors of the plants play took down, when they changed (cell_textures.gd).
func update_hidden_cells() -> void:
	_cell_textures.update_hidden_cells(_cell_size)


## Near plants of species s from mesh [code]levels[s][/code] on cast no mesh shadows (the far tiles'
## casters cast for them: SunflowerField.impostor_shadows_from, SunflowerPlant.impostor_shadows); nearer
## levels cast from their meshes or their shadow twins. 3: every mesh level casts.
func set_impostor_shadows_from(levels: PackedInt32Array) -> void:
	if levels != impostor_shadows_from:
		_cell_textures.forget_masks()  # tiles whose chunks are all near stay drawn for their casters, or not
	impostor_shadows_from = levels
	for i: int in _mesh_nodes.size():
		var node: MultiMeshInstance3D = _mesh_nodes[i]
		var casts: bool = _mesh_node_levels[i] < _casts_from(_mesh_node_species[i])
		if node.get_child_count(true) > 0:
			(node.get_child(0, true) as Node3D).visible = casts  # the twin; the node itself casts none
		else:
			node.cast_shadow = (
				GeometryInstance3D.SHADOW_CASTING_SETTING_ON if casts else GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
			)


## The mesh level from which near plants of [param species] cast from their impostors (3: never).
func _casts_from(species: int) -> int:
	return impostor_shadows_from[species] if species < impostor_shadows_from.size() else PartMeshes.LEVELS


## Shows only the near buckets that hold plants after the simulation's last update: an empty
## MultiMesh would still cost a draw call (and its shadow pass another).
func show_filled_buckets() -> void:
	var filled: PackedByteArray = simulation.get_filled_buckets()
	if filled == _shown_buckets:
		return
	_shown_buckets = filled
	for i: int in _dynamic_nodes.size():
		var bucket: int = _dynamic_buckets[i]
		_dynamic_nodes[i].visible = bucket < filled.size() and filled[bucket] != 0


## Sets where the tiles' impostors end (0: never).
func apply_ranges(max_draw_distance: float) -> void:
	for tile: int in _tile_nodes.size():
		if _tile_nodes[tile]:
			_set_range(tile, max_draw_distance)


## Draws [param species]' near plants with [param plant]'s meshes as drawn now (once the field is
## complete), when it is drawn as the nodes were made (whole or part by part; else the field is
## rebuilt anyway).
func set_plant_meshes(species: int, plant: Resource) -> void:
	if species >= _whole.size() or _whole[species] != plant.drawn_whole():
		return
	var levels: int = Native.constant(&"MESH_LEVEL_COUNT")
	for level: int in levels:
		if _whole[species]:
			_set_bucket_mesh(
				species, Native.mesh_bucket(level, 0), plant.whole_mesh(level), plant.whole_mesh(levels - 1)
			)
			continue
		for part: int in PART_NAMES.size():
			_set_bucket_mesh(
				species,
				Native.mesh_bucket(level, part),
				plant.mesh_for_field(level, part),
				plant.mesh_for_field(levels - 1, part)
			)
	for node: int in _mesh_nodes.size():
		if _mesh_node_species[node] == species:
			_give_instance_parameters(_mesh_nodes[node], plant)


## Gives a near mesh node (and its shadow twin) [param plant]'s instance shader parameters.
func _give_instance_parameters(node: MultiMeshInstance3D, plant: Resource) -> void:
	var twin: MultiMeshInstance3D = node.get_node_or_null(NodePath(CASTER_NAME))
	for parameter: StringName in plant.instance_shader_parameters:
		node.set_instance_shader_parameter(parameter, plant.instance_shader_parameters[parameter])
		if twin:
			twin.set_instance_shader_parameter(parameter, plant.instance_shader_parameters[parameter])


## Draws a near bucket with [param mesh], and its shadow twin (if any) with [param shadow_mesh].
func _set_bucket_mesh(species: int, bucket_in_species: int, mesh: Mesh, shadow_mesh: Mesh) -> void:
	var slot: int = _dynamic_buckets.find(species * Native.constant(&"BUCKET_COUNT") + bucket_in_species)
	if slot < 0:
		return
	var node: MultiMeshInstance3D = _dynamic_nodes[slot]
	var bucket: int = _dynamic_buckets[slot]
	if node.multimesh.mesh != mesh:
		_emptied_for(node.multimesh, mesh)
		node.multimesh.mesh = mesh
		simulation.set_bucket_multimesh(bucket, _filled_rid(node.multimesh))
	var twin: MultiMeshInstance3D = node.get_node_or_null(NodePath(CASTER_NAME))
	if twin and twin.multimesh.mesh != shadow_mesh:
		_emptied_for(twin.multimesh, shadow_mesh)
		twin.multimesh.mesh = shadow_mesh
		simulation.set_bucket_shadow_multimesh(bucket, _filled_rid(twin.multimesh))


## Drops the instances the library wrote into [param multimesh] when it is to draw no mesh
## ([param mesh] null): the renderer refuses a mesh of nothing under instances (an error for each
## part slot a plant of fewer parts left empty when it took the field's plant's place). The library
## allocates them anew when the bucket is given a mesh again.
static func _emptied_for(multimesh: MultiMesh, mesh: Mesh) -> void:
	if mesh == null:
		RenderingServer.multimesh_allocate_data(multimesh.get_rid(), 0, RenderingServer.MULTIMESH_TRANSFORM_3D)


## The RID the library fills for [param multimesh]: none (an invalid RID) while it has no mesh (an
## empty part slot: the renderer refuses instances of nothing).
static func _filled_rid(multimesh: MultiMesh) -> RID:
	return multimesh.get_rid() if multimesh.mesh else RID()


## Adds every node of this field to [param nodes] (as keys), to tell them from foreign children.
func collect(nodes: Dictionary) -> void:
	for list: Array in [_tile_nodes, _dynamic_nodes, _object_nodes]:
		for node: Node in list:
			if node:
				nodes[node] = true


## Frees every node (the simulation forgets its MultiMeshes first).
func free_nodes() -> void:
	simulation.release_multimeshes()
	for nodes: Array in [_tile_nodes, _dynamic_nodes, _object_nodes]:
		for node: Node in nodes:
			if node and is_instance_valid(node):
				node.free()
		nodes.clear()
	_previous = null


## A near bucket's node: the simulation fills its MultiMesh each update and gives the MultiMesh the
## box of the plants it holds then, which the node follows (no box of its own), so that the renderer
## draws the bucket only in the passes its plants reach (the field's box until the first update).
func _add_dynamic(node: MultiMeshInstance3D, bucket: int) -> void:
	node.custom_aabb = AABB()
	simulation.set_bucket_multimesh(bucket, _filled_rid(node.multimesh))
	_dynamic_nodes.append(node)
	_dynamic_buckets.append(bucket)


## Gives the node of near [param bucket] a shadow-only child drawing the same instances with
## [param mesh] (the library fills both MultiMeshes); the node itself casts none.
func _add_shadow_twin(node: MultiMeshInstance3D, bucket: int, mesh: Mesh) -> void:
	node.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	var twin: MultiMeshInstance3D = MultiMeshInstance3D.new()
	twin.name = CASTER_NAME
	twin.multimesh = MultiMesh.new()
	twin.multimesh.mesh = mesh
	twin.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_SHADOWS_ONLY
	node.add_child(twin, false, Node.INTERNAL_MODE_BACK)
	simulation.set_bucket_shadow_multimesh(bucket, _filled_rid(twin.multimesh))


## A MultiMesh node for the native buffers. The library allocates each MultiMesh's data in the
## format of its records (3D transforms and colours, with custom data for whole plants; the
## impostors' compact 8-float records), so the resource's own format is never used.
func _make_node(node_name: String, mesh: Mesh, aabb: AABB) -> MultiMeshInstance3D:
	var multimesh: MultiMesh = MultiMesh.new()
	multimesh.mesh = mesh
	multimesh.custom_aabb = aabb
	var node: MultiMeshInstance3D = MultiMeshInstance3D.new()
	node.name = node_name
	node.multimesh = multimesh
	node.custom_aabb = aabb
	_owner.add_child(node, false, Node.INTERNAL_MODE_BACK)
	return node


## A tile's node is named after the tile's key (where it lies).
func _tile_node_name(tile: int) -> String:
	return "FarTile%d" % tiles.key(tile)


## A tile is hidden once its nearest plant may be past [param max_draw_distance] (the engine
## measures to the box's centre); its plants dither out one after another before that (the impostor
## shader).
func _set_range(tile: int, max_draw_distance: float) -> void:
	var node: MultiMeshInstance3D = _tile_nodes[tile]
	var end: float = 0.0
	if max_draw_distance > 0.0:
		end = max_draw_distance + 0.5 * node.custom_aabb.size.length()
	node.visibility_range_end = end
	_caster_of(node).visibility_range_end = end


## Gives an impostor [param node] a child that draws its shadows from the same MultiMesh with
## [param material] (ImpostorSet.caster: each pixel casts from the depth the plant has there); the
## node itself casts none. The child follows the node's visibility; ranges and shader parameters are
## set on both.
func _add_caster(node: MultiMeshInstance3D, material: ShaderMaterial) -> void:
	node.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	var caster: MultiMeshInstance3D = MultiMeshInstance3D.new()
	caster.name = CASTER_NAME
	caster.multimesh = node.multimesh
	caster.custom_aabb = node.custom_aabb
	caster.material_override = material
	caster.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_SHADOWS_ONLY
	node.add_child(caster, false, Node.INTERNAL_MODE_BACK)


## The shadow caster of an impostor node (see [method _add_caster]).
static func _caster_of(node: MultiMeshInstance3D) -> MultiMeshInstance3D:
	return node.get_child(0, true) as MultiMeshInstance3D


func _field_aabb() -> AABB:
	var box: AABB = AABB()
	for tile: int in tile_table().count:  # the tiles' boxes hold the chunks'
		var tile_box: AABB = tiles.aabb(tile)
		box = tile_box if tile == 0 else box.merge(tile_box)
	return box
