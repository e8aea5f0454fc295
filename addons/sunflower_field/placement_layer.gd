@tool
@icon("icons/placement_layer.svg")
class_name SunflowerPlacementLayer
extends Resource
## One layer of a field's placement rules ([SunflowerPlacementRules]): it places one plant type in
## the cells its filters let through, each cell with the chance
## [member SunflowerPlacementLayer.density] × every filter's weight (0–1). The filters multiply;
## each is off until its [code]…_use[/code] switch is on.
## Positions are in the field's space, in metres (x along the map's columns, z along its rows).

## How the layer's cells meet what earlier layers placed.
enum Mode {
	PLACE,  ## Its plants take the cells they pass, over earlier layers' plants.
	FILL,  ## Its plants take only cells still empty.
	ERASE,  ## Cells it passes are emptied (a clearing, a road's verge).
}

## The plant type it places: [code]*[/code] (the field's [member SunflowerField.plant]) or a
## symbol of the field's legend that names a [SunflowerPlant]. Not read by [constant Mode].ERASE.
@export var plant: String = "*"
## How its cells meet what earlier layers placed (see [enum Mode]).
@export var mode: Mode = Mode.PLACE
## The share of cells it takes where every filter gives 1.
@export_range(0.0, 1.0, 0.01) var density: float = 1.0

@export_group("Height", "height_")
## Filters by the ground's height at the cell: 1 from [member height_min] to [member height_max],
## falling to 0 over [member height_falloff] metres outside.
@export var height_use: bool = false
## The range's low end, metres in the field's space.
@export var height_min: float = 0.0
## The range's high end, metres.
@export var height_max: float = 10.0
## Metres outside the range over which the weight falls from 1 to 0 (0: a sharp edge).
@export_range(0.0, 100.0, 0.1, "or_greater", "suffix:m") var height_falloff: float = 0.0
## The other way round: 0 in the range, 1 outside.
@export var height_invert: bool = false

@export_group("Slope", "slope_")
## Filters by the ground's slope at the cell (degrees from level, from the heights around it): 1
## from [member slope_min] to [member slope_max], falling to 0 over [member slope_falloff] degrees.
@export var slope_use: bool = false
## The range's low end, degrees from level.
@export_range(0.0, 90.0, 0.1, "suffix:°") var slope_min: float = 0.0
## The range's high end, degrees.
@export_range(0.0, 90.0, 0.1, "suffix:°") var slope_max: float = 30.0
## Degrees outside the range over which the weight falls from 1 to 0 (0: a sharp edge).
@export_range(0.0, 90.0, 0.1, "suffix:°") var slope_falloff: float = 0.0
## The other way round: 0 in the range, 1 outside (plants only on steep ground).
@export var slope_invert: bool = false

@export_group("Noise", "noise_")
## Filters by seeded value noise (0–1, in patches [member noise_scale] metres across): 0 below
## [member noise_threshold], 1 from threshold + [member noise_falloff] on.
@export var noise_use: bool = false
## Metres across a patch of the first octave.
@export_range(0.1, 1000.0, 0.1, "or_greater", "suffix:m") var noise_scale: float = 20.0
## Finer detail: each octave half the size and half the weight of the one before.
@export_range(1, 8) var noise_octaves: int = 3
## The noise value below which the weight is 0: higher, fewer and smaller patches.
@export_range(0.0, 1.0, 0.01) var noise_threshold: float = 0.5
## How far above the threshold the weight reaches 1 (0: patches with sharp edges).
@export_range(0.0, 1.0, 0.01) var noise_falloff: float = 0.1
## Another pattern for the same rules' seed (two layers with one noise seed share their patches).
@export var noise_seed: int = 0
## The other way round: plants between the patches.
@export var noise_invert: bool = false

@export_group("Mask", "mask_")
## Filters by one channel of an image laid over a rectangle of the field (a terrain's splat map, a
## painted mask): its value, 0–1, bilinear between pixels; the image's top row at the rectangle's
## low z (the map's first row).
@export var mask_use: bool = false
## The image (imported textures are read back from the GPU's copy; a compressed one is decompressed).
@export var mask_texture: Texture2D
## The channel read as the weight (a splat map keeps one ground texture per channel).
@export_enum("Red", "Green", "Blue", "Alpha") var mask_channel: int = 0
## The rectangle the image covers: x, z of its low corner and its size, in metres. Empty: the whole field.
@export var mask_rect: Rect2 = Rect2()
## The weight outside the rectangle.
@export_range(0.0, 1.0, 0.01) var mask_outside: float = 0.0
## The other way round: 1 − the channel.
@export var mask_invert: bool = false

@export_group("Paths", "paths_")
## Keeps plants off roads and rivers: 0 within [member paths_half_width] of any of the
## [Path3D] nodes' curves (as seen from above), 1 from [member paths_falloff] further on.
@export var paths_use: bool = false
## The [Path3D] nodes, as paths from the field.
@export var paths_nodes: Array[NodePath] = []
## Metres either side of a curve with no plant.
@export_range(0.0, 100.0, 0.1, "or_greater", "suffix:m") var paths_half_width: float = 2.0
## Metres beyond the half width over which the weight rises from 0 to 1 (0: a sharp verge).
@export_range(0.0, 100.0, 0.1, "or_greater", "suffix:m") var paths_falloff: float = 1.0
## Plants only near the paths (reeds along a river).
@export var paths_invert: bool = false

@export_group("Exclusion", "exclusion_")
## Keeps plants out of the footprints (as seen from above) of the collision shapes of every
## [CollisionObject3D] in the field's scene on one of [member exclusion_layers]: buildings, rocks.
@export var exclusion_use: bool = false
## The physics layers whose bodies and areas keep plants out.
@export_flags_3d_physics var exclusion_layers: int = 1
## Metres outside a footprint over which the weight rises from 0 to 1.
@export_range(0.0, 100.0, 0.1, "or_greater", "suffix:m") var exclusion_falloff: float = 0.0

@export_group("Spacing", "spacing_")
## No plant of this layer within [member spacing_distance] of a plant an earlier layer placed (no
## grass at a tree's trunk).
@export var spacing_use: bool = false
## The earlier layer, counted from 1.
@export_range(1, 64) var spacing_layer: int = 1
## Metres, centre to centre, kept from the earlier layer's plants (up to 64 cells).
@export_range(0.0, 32.0, 0.1, "or_greater", "suffix:m") var spacing_distance: float = 1.5
