@tool
extends RefCounted
## The textures the impostor shader reads about a field's cells, kept in step with its simulation:
## per species the active-chunk mask (a byte per chunk cell, 255 where the near buckets draw the
## chunk, so the tiles skip those plants), and the cells whose plant play took down (a bit a cell).
## Each is updated in place when the simulation's version of it changed.

const NativeField: GDScript = preload("../native/native_field.gd")
const ImpostorSet: GDScript = preload("impostor_set.gd")
## The hidden cells' texture is this many bytes wide (the shader's HIDDEN_TEXTURE_WIDTH).
const HIDDEN_TEXTURE_WIDTH: int = 4096

var _simulation: NativeField
var _impostors: Array[ImpostorSet]  # per species
var _masks: Array[ImageTexture] = []  # per species: which chunk cells the near buckets draw
var _mask_version: int = -1  # the simulation's mask version the textures show
var _hidden: ImageTexture  # the cells whose plant play took down, once there are any
var _hidden_version: int = -1  # the simulation's hidden-cells version it shows


## The textures of [param simulation]'s cells, given to [param impostors] (an ImpostorSet per species).
func _init(simulation: NativeField, impostors: Array[ImpostorSet]) -> void:
	_simulation = simulation
	_impostors = impostors


## Whether the simulation's masks changed since the last [method update_masks] (which then shows them).
func masks_changed() -> bool:
	return _simulation.get_mask_version() != _mask_version


## Shows the masks again at the next [method update_masks], changed or not.
func forget_masks() -> void:
	_mask_version = -1


## Gives each species' impostor material its mask of the chunks the near buckets draw now.
func update_masks() -> void:
	_mask_version = _simulation.get_mask_version()
	var grid: PackedInt32Array = _simulation.get_chunk_grid()
	if grid[0] * grid[1] == 0:
		return  # no field laid out
	for species: int in _simulation.get_species_count():
		var image: Image = Image.create_from_data(
			grid[0], grid[1], false, Image.FORMAT_R8, _simulation.get_active_mask(species)
		)
		if species >= _masks.size():
			_masks.append(null)
		_masks[species] = _show_image(_masks[species], image)
		_impostors[species].set_active_chunks(_masks[species], grid[0])


## Hides the impostors of the plants play took down (the simulation's hidden cells), when they
## changed: a bit a cell, laid out in rows of [constant HIDDEN_TEXTURE_WIDTH] bytes for the shader.
func update_hidden_cells(cell_size: float) -> void:
	var version: int = _simulation.get_hidden_version()
	if version == _hidden_version:
		return
	_hidden_version = version
	var bytes: PackedByteArray = _simulation.get_hidden_cells()
	if bytes.is_empty():
		for impostors: ImpostorSet in _impostors:
			impostors.set_shared(&"hidden_cell_size", 0.0)  # nothing hidden
		return
	var row_bytes: int = bytes.size() / _simulation.get_map_rows()  # (the simulation's rows of bits)
	var width: int = mini(bytes.size(), HIDDEN_TEXTURE_WIDTH)
	var height: int = ceili(float(bytes.size()) / width)
	bytes.resize(width * height)
	_hidden = _show_image(_hidden, Image.create_from_data(width, height, false, Image.FORMAT_R8, bytes))
	for impostors: ImpostorSet in _impostors:
		impostors.set_shared(&"hidden_cells", _hidden)
		impostors.set_shared(&"hidden_row_bytes", row_bytes)
		impostors.set_shared(&"hidden_cell_size", cell_size)


## [param texture] showing [param image] now: updated in place when it has the image's size, else
## made (or given the image) anew.
static func _show_image(texture: ImageTexture, image: Image) -> ImageTexture:
	if texture == null:
		return ImageTexture.create_from_image(image)
	if texture.get_size() != Vector2(image.get_size()):
		texture.set_image(image)
	else:
		texture.update(image)
	return texture
