@tool
extends RefCounted
## What the bake measures on a plant's views atlas (as baked, not premultiplied), read from the
## alpha of each mip level as the import makes them: the alpha cut that keeps each level's cover
## ([member SunflowerPlant.impostor_alpha_cuts]) and the level from which the plant is thin
## ([member SunflowerPlant.impostor_thin_from]).

const ImpostorBaker: GDScript = preload("impostor_baker.gd")

## The alpha cut against which [method thin_from] measures a plant's thinness (the field's default
## [member SunflowerField.alpha_scissor]).
const THIN_CUT: float = 0.5
## The latest mip level [method thin_from] reports: where the far test is hashed for every plant
## anyway (the shader's hashed_from + 1), a thin level changes nothing but the reprojection, which
## the built-in sunflower's far fields were measured with.
const THIN_LATEST: float = 3.0


## Gives [param plant] what the bake measures on its views [param views] (as baked, not
## premultiplied): [member SunflowerPlant.impostor_alpha_cuts] and
## [member SunflowerPlant.impostor_thin_from]. For views baked earlier and loaded from their file.
static func measure(plant: SunflowerPlant, views: Image) -> void:
	var alphas: Array[PackedInt32Array] = alpha_levels(views)
	plant.impostor_alpha_cuts = alpha_cuts(alphas)
	plant.impostor_thin_from = thin_from(alphas, finer_levels(views))


## How many mip levels finer than ImpostorBaker.CELL_PIXELS a view square of the atlas
## [param views] is (1 for a thin plant's views, 0 for others').
static func finer_levels(views: Image) -> float:
	var square: float = float(views.get_height()) / SunflowerPlant.ATLAS_VIEWS.y
	return maxf(log(square / ImpostorBaker.CELL_PIXELS) / log(2.0), 0.0)


## How many texels of each alpha (0–255) each mip level of the views [param image] holds, as the
## import makes the levels (alpha averaged): [method alpha_cuts] and [method thin_from] read them.
static func alpha_levels(image: Image) -> Array[PackedInt32Array]:
	var levels: Image = image.duplicate() as Image
	levels.clear_mipmaps()
	levels.convert(Image.FORMAT_RGBA8)
	levels.generate_mipmaps()
	var data: PackedByteArray = levels.get_data()
	var out: Array[PackedInt32Array] = []
	for level: int in levels.get_mipmap_count() + 1:
		var end: int = levels.get_mipmap_offset(level + 1) if level < levels.get_mipmap_count() else data.size()
		var counts: PackedInt32Array = []
		counts.resize(256)
		for k: int in range(levels.get_mipmap_offset(level) + 3, end, 4):
			counts[data[k]] += 1
		out.append(counts)
	return out


## The alpha cut of each mip level of the views ([param levels], [method alpha_levels]) that keeps
## the views' cover: the highest cut that at least the share of the level's texels reaches that the
## views' mean alpha gives (a leaf a fraction of a texel wide is that fraction of alpha, below a fixed
## cut; the test on this cut draws as many texels as the leaves cover). See
## [member SunflowerPlant.impostor_alpha_cuts].
static func alpha_cuts(levels: Array[PackedInt32Array]) -> PackedFloat32Array:
	var cuts: PackedFloat32Array = []
	for counts: PackedInt32Array in levels:
		var covered: float = 0.0  # the mean alpha's worth of texels
		for alpha: int in 256:
			covered += counts[alpha] * alpha / 255.0
		var cut: int = 255
		var reached: int = counts[255]
		while cut > 1 and reached < covered:
			cut -= 1
			reached += counts[cut]
		cuts.append(cut / 255.0)
	return cuts


## The mip level of the views ([param levels], [method alpha_levels]) from which the plant is
## *thin*: where a plain alpha cut ([constant THIN_CUT]) keeps less than half of what its texels
## cover, interpolated between the two levels about that share (a crown of leaves smaller than a
## texel: most of its cover is in texels a fraction covered). −1 when that comes after
## [constant THIN_LATEST] (the built-in sunflower's views cross it at 3.8; [param finer] levels later
## for views that many levels finer than ImpostorBaker.CELL_PIXELS), or never. See
## [member SunflowerPlant.impostor_thin_from].
static func thin_from(levels: Array[PackedInt32Array], finer: float = 0.0) -> float:
	var cut: int = ceili(THIN_CUT * 255.0)
	var latest: float = THIN_LATEST + finer
	var before: float = 1.0  # the share kept at the level before
	for level: int in mini(levels.size(), ceili(latest) + 1):
		var all: int = 0
		var kept: int = 0
		for alpha: int in 256:
			all += levels[level][alpha] * alpha
			kept += levels[level][alpha] * alpha if alpha >= cut else 0
		var share: float = float(kept) / all if all > 0 else 1.0
		if share < 0.5:
			var crossed: float = level - (0.5 - share) / maxf(before - share, 1e-6) if level > 0 else 0.0
			return crossed if crossed <= latest else -1.0
		before = share
	return -1.0
