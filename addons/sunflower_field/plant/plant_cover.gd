@tool
extends RefCounted
## What a plant's triangles cover seen along each of [constant VIEWS]: a grid of cells over its bounds
## for each, cells of [constant CELLS]th of the bounds' longest side, a cell covered where a triangle covers
## its centre and its texture there is not cut out ([method cut_out]). A cheap stand-in for the
## pixels a plant covers from afar, for thinning its levels to the cover of its first.

## Cells along the bounds' longest side.
const CELLS: int = 64
## The directions the plant is seen along: from the side (x, z), from above, and from 45° above.
const VIEWS: Array[Vector3] = [
	Vector3(1, 0, 0),
	Vector3(0, 0, 1),
	Vector3(0, 1, 0),
	Vector3(0, 0.7071068, 0.7071068),
	Vector3(0.7071068, 0.7071068, 0)
]


## Empty grids over [param bounds], one per view of [param views] ([constant VIEWS], or some of
## them: a big plant's cover is measured in one): [code]{"bounds", "cell", "axes": [Basis] (a view's
## grid's x and y directions, and its origin's offset in the basis' z), "corners": [Vector2],
## "sides": [Vector2i], "grids": [PackedByteArray]}[/code].
static func empty(bounds: AABB, views: Array[Vector3] = VIEWS) -> Dictionary:
	var cell: float = maxf(bounds.get_longest_axis_size(), 1e-6) / CELLS
	var axes: Array[Basis] = []
	var corners: Array[Vector2] = []
	var sides: Array[Vector2i] = []
	var grids: Array[PackedByteArray] = []
	for view: Vector3 in views:
		var across: Vector3 = (Vector3.UP if absf(view.y) < 0.9 else Vector3.BACK).cross(view).normalized()
		var up: Vector3 = view.cross(across)
		var low: Vector2 = Vector2(INF, INF)
		var high: Vector2 = -low
		for corner: int in 8:
			var at: Vector3 = bounds.get_endpoint(corner)
			low = low.min(Vector2(at.dot(across), at.dot(up)))
			high = high.max(Vector2(at.dot(across), at.dot(up)))
		axes.append(Basis(across / cell, up / cell, Vector3.ZERO))
		corners.append(low / cell)
		var side: Vector2i = Vector2i(maxi(1, ceili((high.x - low.x) / cell)), maxi(1, ceili((high.y - low.y) / cell)))
		sides.append(side)
		var grid: PackedByteArray = []
		grid.resize(side.x * side.y)
		grids.append(grid)
	return {"bounds": bounds, "cell": cell, "axes": axes, "corners": corners, "sides": sides, "grids": grids}


## Draws a surface's triangles ([param arrays]) into [param cover]'s grids, where [param mask] (its
## material's [method cut_out]) is not cut out: row by row, each row's cells between the triangle's
## edges (a thin card standing across the grid visits the cells it covers, not its bounding box).
static func draw(cover: Dictionary, arrays: Array, mask: Dictionary) -> void:
	var positions: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
	var indices: PackedInt32Array = arrays[Mesh.ARRAY_INDEX]
	var uvs: PackedVector2Array = (
		arrays[Mesh.ARRAY_TEX_UV] if arrays[Mesh.ARRAY_TEX_UV] != null else PackedVector2Array()
	)
	var masked: bool = not mask.is_empty() and uvs.size() == positions.size()
	var mask_size: Vector2i = mask.get("size", Vector2i.ONE)
	var opaque: PackedByteArray = mask.get("opaque", PackedByteArray())
	var uv_scale: Vector2 = mask.get("uv_scale", Vector2.ONE)
	var uv_offset: Vector2 = mask.get("uv_offset", Vector2.ZERO)
	var across_x: Array[float] = [0.0, 0.0, 0.0]  # per edge of a triangle: its x at y = 0, its dx/dy
	var across_slope: Array[float] = [0.0, 0.0, 0.0]
	var bounding: Array[int] = [0, 0, 0]
	for view: int in (cover.axes as Array).size():
		var axes: Basis = cover.axes[view]
		var corner: Vector2 = cover.corners[view]
		var side: Vector2i = cover.sides[view]
		var grid: PackedByteArray = cover.grids[view]
		var flat: PackedVector2Array = []  # the positions in the view's grid
		flat.resize(positions.size())
		for vertex: int in positions.size():
			flat[vertex] = Vector2(axes.x.dot(positions[vertex]), axes.y.dot(positions[vertex])) - corner
		for k: int in range(0, indices.size() - 2, 3):
			var a: Vector2 = flat[indices[k]]
			var b: Vector2 = flat[indices[k + 1]]
			var c: Vector2 = flat[indices[k + 2]]
			var twice_area: float = (b - a).cross(c - a)
			if twice_area == 0.0:
				continue
			# The rows whose cells' centres (x + 0.5, y + 0.5) the triangle's height spans.
			var first_row: int = maxi(0, ceili(minf(a.y, minf(b.y, c.y)) - 0.5))
			var last_row: int = mini(side.y - 1, floori(maxf(a.y, maxf(b.y, c.y)) - 0.5))
			if last_row < first_row:
				continue
			# The texture coordinates at a cell's centre: uv_a + uv_x * (x - a.x) + uv_y * (y - a.y).
			var uv_a: Vector2 = Vector2.ZERO
			var uv_x: Vector2 = Vector2.ZERO
			var uv_y: Vector2 = Vector2.ZERO
			if masked:
				uv_a = uvs[indices[k]] * uv_scale + uv_offset
				var to_b: Vector2 = (uvs[indices[k + 1]] - uvs[indices[k]]) * uv_scale
				var to_c: Vector2 = (uvs[indices[k + 2]] - uvs[indices[k]]) * uv_scale
				uv_x = (to_b * (c - a).y - to_c * (b - a).y) / twice_area
				uv_y = (to_c * (b - a).x - to_b * (c - a).x) / twice_area
			# Each edge p → q keeps the centres on the triangle's side of it: where it is not level, a
			# row's x at most (or at least) where the edge crosses the row, x = p.x + (y - p.y) dx/dy.
			for edge: int in 3:
				var p: Vector2 = a if edge == 0 else (b if edge == 1 else c)
				var along: Vector2 = (b if edge == 0 else (c if edge == 1 else a)) - p
				across_x[edge] = p.x - p.y * along.x / along.y if along.y != 0.0 else 0.0
				across_slope[edge] = along.x / along.y if along.y != 0.0 else 0.0
				bounding[edge] = int(signf(along.y * twice_area))  # 1: a high bound, -1: a low one
			for y: int in range(first_row, last_row + 1):
				var row_y: float = y + 0.5
				var low: float = -INF
				var high: float = INF
				for edge: int in 3:
					if bounding[edge] > 0:
						high = minf(high, across_x[edge] + row_y * across_slope[edge])
					elif bounding[edge] < 0:
						low = maxf(low, across_x[edge] + row_y * across_slope[edge])
				var from: int = maxi(0, ceili(low - 0.5))
				var to: int = mini(side.x - 1, floori(high - 0.5))
				var row: int = y * side.x
				for x: int in range(from, to + 1):
					if masked:
						var uv: Vector2 = uv_a + uv_x * (x + 0.5 - a.x) + uv_y * (row_y - a.y)
						var texel: Vector2i = Vector2i(
							posmod(floori(uv.x * mask_size.x), mask_size.x),
							posmod(floori(uv.y * mask_size.y), mask_size.y)
						)
						if not opaque[texel.y * mask_size.x + texel.x]:
							continue
					grid[row + x] = 1
		cover.grids[view] = grid


## A copy of [param cover] whose grids are drawn into apart from its own.
static func copied(cover: Dictionary) -> Dictionary:
	var grids: Array[PackedByteArray] = []
	for grid: PackedByteArray in cover.grids:
		grids.append(grid.duplicate())
	var out: Dictionary = cover.duplicate()
	out.grids = grids
	return out


## The cells [param cover] has covered, over its views.
static func covered(cover: Dictionary) -> int:
	var total: int = 0
	for grid: PackedByteArray in cover.grids:
		total += grid.count(1)
	return total


## Where [param material]'s texture is cut out: [code]{"size": Vector2i, "opaque": PackedByteArray,
## "uv_scale": Vector2, "uv_offset": Vector2}[/code] (1 where alpha is at or above its cut-off, 0.5 for
## blended or hashed alpha) of a BaseMaterial3D's albedo texture when its transparency is on, read
## where its UV1 scale and offset put a vertex's UV (a glTF texture transform, a leaf atlas), or of a
## ShaderMaterial's first texture parameter with alpha, at the UV as it is; empty for any other
## material, a triplanar one, or a texture whose pixels cannot be read (nothing cut out).
static func cut_out(material: Material) -> Dictionary:
	var texture: Texture2D = null
	var threshold: float = 0.5
	var uv_scale: Vector2 = Vector2.ONE
	var uv_offset: Vector2 = Vector2.ZERO
	if material is BaseMaterial3D:
		var base: BaseMaterial3D = material as BaseMaterial3D
		if base.transparency == BaseMaterial3D.TRANSPARENCY_DISABLED or base.uv1_triplanar:
			return {}
		texture = base.albedo_texture
		uv_scale = Vector2(base.uv1_scale.x, base.uv1_scale.y)
		uv_offset = Vector2(base.uv1_offset.x, base.uv1_offset.y)
		if base.transparency == BaseMaterial3D.TRANSPARENCY_ALPHA_SCISSOR:
			threshold = base.alpha_scissor_threshold
	elif material is ShaderMaterial and (material as ShaderMaterial).shader != null:
		for parameter: Dictionary in (material as ShaderMaterial).shader.get_shader_uniform_list():
			var value: Variant = (material as ShaderMaterial).get_shader_parameter(parameter.name)
			if value is Texture2D and _pixels(value) != null and _pixels(value).detect_alpha() != Image.ALPHA_NONE:
				texture = value
				break
	var image: Image = _pixels(texture)
	if image == null:
		return {}
	var opaque: PackedByteArray = []
	opaque.resize(image.get_width() * image.get_height())
	for y: int in image.get_height():
		for x: int in image.get_width():
			opaque[y * image.get_width() + x] = 1 if image.get_pixel(x, y).a >= threshold else 0
	return {"size": image.get_size(), "opaque": opaque, "uv_scale": uv_scale, "uv_offset": uv_offset}


## [param texture]'s pixels, at most 64 a side, or null.
static func _pixels(texture: Texture2D) -> Image:
	var image: Image = texture.get_image() if texture != null else null
	if image == null or image.is_empty():
		return null
	image = image.duplicate() as Image
	if image.is_compressed() and image.decompress() != OK:
		return null
	image.convert(Image.FORMAT_RGBA8)
	if image.get_width() > 64 or image.get_height() > 64:
		image.resize(mini(64, image.get_width()), mini(64, image.get_height()), Image.INTERPOLATE_BILINEAR)
	return image
