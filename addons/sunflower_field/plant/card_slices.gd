@tool
extends RefCounted
## Tall foliage cards cut into slices so that they bend: a plant of one part bends each vertex by its
## height (plant_bend.gdshaderinc), so a blade that is one quad from the ground to the top would lean
## as a rigid card. Each triangle of a card that stands on the plant's base and spans more than
## [constant SPANNING] of its height is cut by the planes y = k × height / [constant SLICES], its vertices' attributes
## interpolated along the edges they cut; neighbouring triangles share each cut vertex, so the card
## stays whole as it bends. Other cards (leaves on a tree) lean as they are: over their own height
## the bend is nearly straight. (A standing card keeps its height at every level: the thinned levels
## grow it only in width, so a coarser level never has more sliced cards.)

## Slices a plant's height is cut into: the bend is drawn as that many straight pieces (a point a
## tenth of the way up a sliced blade moves 0.025 of its top's move, against 0.1 leaning rigidly).
const SLICES: int = 4
## The share of the plant's height a card must span to be sliced.
const SPANNING: float = 0.5
const MeshPieces: GDScript = preload("mesh_pieces.gd")


## [param arrays] (a surface's) with the triangles of its cards standing on the base of [param bounds]
## (the plant's level 1's; the root at y = 0) and spanning more than [constant SPANNING] of its
## height cut at the slices' planes; the surface as it is when it is not of cards or has none such.
static func sliced(arrays: Array, bounds: AABB) -> Array:
	var pieces: MeshPieces = MeshPieces.new(arrays)
	var height: float = bounds.end.y
	if not pieces.are_cards() or height <= 0.0:
		return arrays
	var positions: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
	var indices: PackedInt32Array = arrays[Mesh.ARRAY_INDEX]
	var slice: float = height / SLICES
	var top: PackedFloat32Array = []
	top.resize(pieces.count)
	top.fill(-INF)
	for k: int in indices.size():
		top[pieces.piece_of[k / 3]] = maxf(top[pieces.piece_of[k / 3]], positions[indices[k]].y)
	var standing_below: float = bounds.position.y + MeshPieces.STANDING_SHARE * bounds.size.y
	var tall: PackedByteArray = []
	tall.resize(pieces.count)
	for piece: int in pieces.count:
		var spans: bool = top[piece] - pieces.lowest[piece] > SPANNING * height
		tall[piece] = 1 if pieces.is_card(piece) and pieces.lowest[piece] <= standing_below and spans else 0
	if tall.count(1) == 0:
		return arrays
	var out: Dictionary = {"arrays": arrays, "slice": slice, "made": {}, "sources": [], "indices": PackedInt32Array()}
	for triangle: int in indices.size() / 3:
		var corners: PackedInt32Array = indices.slice(3 * triangle, 3 * triangle + 3)
		var piece: int = pieces.piece_of[triangle]
		if tall[piece]:
			_cut(out, corners, slice)
		else:
			for corner: int in corners:
				out.indices.append(_vertex(out, [corner, corner, 0]))
	return _written(out)


## Cuts the triangle [param corners] at the planes y = k × [param slice] into [param out].
static func _cut(out: Dictionary, corners: PackedInt32Array, slice: float) -> void:
	var positions: PackedVector3Array = out.arrays[Mesh.ARRAY_VERTEX]
	var order: Array = Array(corners)
	order.sort_custom(func(a: int, b: int) -> bool: return positions[a].y < positions[b].y)
	var low: int = order[0]
	var middle: int = order[1]
	var high: int = order[2]
	var facing: Vector3 = (positions[corners[1]] - positions[corners[0]]).cross(
		positions[corners[2]] - positions[corners[0]]
	)
	var bottom: float = positions[low].y
	var ceiling: float = positions[high].y
	# The planes between the bottom and the top, then the slabs between them.
	var levels: PackedFloat32Array = [bottom]
	for k: int in range(floori(bottom / slice) + 1, ceili(ceiling / slice)):
		levels.append(k * slice)
	levels.append(ceiling)
	for k: int in levels.size() - 1:
		if levels[k + 1] <= levels[k]:
			continue
		# A slab's outline: the long edge (low to high) at its bottom and top, then the short edges
		# (low to middle to high) at its top, the middle corner when within, and at its bottom.
		var below: int = roundi(levels[k] / slice)  # the planes' numbers (where a level is one)
		var above: int = roundi(levels[k + 1] / slice)
		var outline: Array = [
			_on_edge(out, low, high, levels[k], below),
			_on_edge(out, low, high, levels[k + 1], above),
			_on_short_edges(out, low, middle, high, levels[k + 1], above),
		]
		if positions[middle].y > levels[k] and positions[middle].y < levels[k + 1]:
			outline.append(_vertex(out, [middle, middle, 0]))
		outline.append(_on_short_edges(out, low, middle, high, levels[k], below))
		var polygon: Array = []
		for vertex: int in outline:
			if polygon.is_empty() or (polygon[-1] != vertex and polygon[0] != vertex):
				polygon.append(vertex)
		for fan: int in range(1, polygon.size() - 1):
			var triangle: Array = [polygon[0], polygon[fan], polygon[fan + 1]]
			var made: Vector3 = (_place(out, triangle[1]) - _place(out, triangle[0])).cross(
				_place(out, triangle[2]) - _place(out, triangle[0])
			)
			if made.dot(facing) < 0.0:  # keep the triangle's winding: its front stays its front
				triangle = [triangle[0], triangle[2], triangle[1]]
			out.indices.append_array(PackedInt32Array(triangle))


## The vertex at height [param y] on the edge from [param a] to [param b] (the k-th plane's, or a
## corner when it is there).
static func _on_edge(out: Dictionary, a: int, b: int, y: float, plane: int) -> int:
	var positions: PackedVector3Array = out.arrays[Mesh.ARRAY_VERTEX]
	if y <= positions[a].y:
		return _vertex(out, [a, a, 0])
	if y >= positions[b].y:
		return _vertex(out, [b, b, 0])
	return _vertex(out, [mini(a, b), maxi(a, b), plane])


## The vertex at height [param y] on the short edges (low to middle to high): the middle corner at
## its own height (where the triangle has a flat bottom or top, the corner that is not on the long edge).
static func _on_short_edges(out: Dictionary, low: int, middle: int, high: int, y: float, plane: int) -> int:
	var positions: PackedVector3Array = out.arrays[Mesh.ARRAY_VERTEX]
	if y == positions[middle].y:
		return _vertex(out, [middle, middle, 0])
	return _on_edge(out, low, middle, y, plane) if y < positions[middle].y else _on_edge(out, middle, high, y, plane)


## The output vertex of [param source] ([code][a, b, plane][/code]: corner a when a = b, else where
## the k-th plane cuts the edge a–b), made the first time it is asked for.
static func _vertex(out: Dictionary, source: Array) -> int:
	var key: Vector3i = Vector3i(source[0], source[1], source[2] if source[0] != source[1] else 0)
	if not out.made.has(key):
		out.made[key] = out.sources.size()
		out.sources.append(key)
	return out.made[key]


static func _place(out: Dictionary, vertex: int) -> Vector3:
	var key: Vector3i = out.sources[vertex]
	var positions: PackedVector3Array = out.arrays[Mesh.ARRAY_VERTEX]
	return positions[key.x].lerp(positions[key.y], _share(out, key))


## How far along its edge a cut vertex lies (0 for a corner).
static func _share(out: Dictionary, key: Vector3i) -> float:
	if key.x == key.y:
		return 0.0
	var positions: PackedVector3Array = out.arrays[Mesh.ARRAY_VERTEX]
	var y: float = out.slice * key.z
	return clampf((y - positions[key.x].y) / (positions[key.y].y - positions[key.x].y), 0.0, 1.0)


## The output arrays: every kind the surface has, interpolated for the cut vertices.
static func _written(out: Dictionary) -> Array:
	var arrays: Array = out.arrays
	var written: Array = []
	written.resize(Mesh.ARRAY_MAX)
	for kind: int in MeshPieces.VERTEX_ARRAYS:
		if arrays[kind] == null:
			continue
		var values: Variant = arrays[kind]
		var made: Variant = values.duplicate()
		var width: int = 4 if kind == Mesh.ARRAY_TANGENT else 1
		made.resize(out.sources.size() * width)
		for vertex: int in out.sources.size():
			var key: Vector3i = out.sources[vertex]
			var share: float = _share(out, key)
			for part: int in width:
				var a: Variant = values[key.x * width + part]
				var b: Variant = values[key.y * width + part]
				if share == 0.0 or part == 3:  # a corner, or a tangent's side
					made[vertex * width + part] = a
				elif width == 4:
					made[vertex * width + part] = lerpf(a, b, share)
				else:
					made[vertex * width + part] = a.lerp(b, share)
			if kind == Mesh.ARRAY_NORMAL:
				made[vertex] = (made[vertex] as Vector3).normalized()
		written[kind] = made
	written[Mesh.ARRAY_INDEX] = out.indices
	return written
