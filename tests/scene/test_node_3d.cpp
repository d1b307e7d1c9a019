/**************************************************************************/
/*  test_node_3d.cpp                                                      */
/**************************************************************************/
/* Node tree basics, Node3D transforms (YXZ Euler, global propagation to  */
/* the server), visibility, Camera3D, MeshInstance3D, WorldEnvironment.   */

#include "scene/3d/node_3d.h"

#include "scene/3d/camera_3d.h"
#include "scene/3d/light_3d.h"
#include "scene/3d/mesh_instance_3d.h"
#include "scene/3d/world_environment.h"
#include "scene/main/scene_tree.h"
#include "scene/resources/primitive_meshes.h"
#include "tests/scene/scene_test_fixture.h"

#include <doctest/doctest.h>

#include <cmath>

namespace TestNode3D {

using SceneTest::DummyServer;
using SceneTest::ErrorCatcher;

// Records the tree notifications it receives, tagged with its name.
class NotificationLog : public Node3D {
	GDCLASS(NotificationLog, Node3D);

protected:
	void _notification(int p_what) {
		if (log && (p_what == NOTIFICATION_ENTER_TREE || p_what == NOTIFICATION_EXIT_TREE || p_what == NOTIFICATION_READY)) {
			const char *what = p_what == NOTIFICATION_ENTER_TREE ? "enter" : (p_what == NOTIFICATION_EXIT_TREE ? "exit" : "ready");
			log->push_back(get_name() + ":" + what);
		}
		if (p_what == NOTIFICATION_TRANSFORM_CHANGED) {
			transform_changes++;
		}
	}

public:
	std::vector<String> *log = nullptr;
	int transform_changes = 0;
};

TEST_CASE("[Node] children, names, paths and ownership") {
	DummyServer server;
	ErrorCatcher errors;
	Node *root = new Node;
	root->set_name("Root");
	Node *a = new Node;
	a->set_name("A");
	Node *b = new Node;
	b->set_name("B");
	root->add_child(a);
	a->add_child(b);

	CHECK(root->get_child_count() == 1);
	CHECK(root->get_child(0) == a);
	CHECK(root->get_child(-1) == a);
	CHECK(root->get_node("A/B") == b);
	CHECK(b->get_node("..") == a);
	CHECK(b->get_node("../..") == root);
	CHECK(b->get_node(".") == b);
	CHECK(b->get_node_or_null("../C") == nullptr);
	CHECK(root->get_node("/Root/A/B") == b);
	CHECK(b->get_path() == "Root/A/B");

	SUBCASE("duplicate and empty names are made unique") {
		Node *dup = new Node;
		dup->set_name("A");
		root->add_child(dup);
		CHECK(dup->get_name() == "A2");
		Node3D *unnamed = new Node3D;
		root->add_child(unnamed);
		CHECK(unnamed->get_name() == "Node3D");
	}
	SUBCASE("invalid additions are refused") {
		root->add_child(nullptr);
		root->add_child(root);
		a->add_child(root);
		Node *other = new Node;
		other->add_child(b);
		CHECK(b->get_parent() == a);
		CHECK(errors.messages.size() == 4);
		delete other;
	}
	SUBCASE("remove_child gives ownership back") {
		a->remove_child(b);
		CHECK(b->get_parent() == nullptr);
		CHECK(a->get_child_count() == 0);
		delete b;
	}
	SUBCASE("invalid characters in names are replaced") {
		a->set_name("bad/name");
		CHECK(a->get_name() == "bad_name");
	}
	delete root; // Deletes the subtree.
}

TEST_CASE("[Node] tree notifications: enter top-down, ready bottom-up, exit bottom-up") {
	DummyServer server;
	std::vector<String> log;
	SceneTree *tree = new SceneTree;
	NotificationLog *p = new NotificationLog;
	p->set_name("P");
	p->log = &log;
	NotificationLog *c = new NotificationLog;
	c->set_name("C");
	c->log = &log;
	p->add_child(c);
	CHECK(log.empty());
	CHECK_FALSE(c->is_inside_tree());

	tree->get_root()->add_child(p);
	CHECK(c->is_inside_tree());
	CHECK(c->get_tree() == tree);
	CHECK(c->get_path() == "/root/P/C");
	REQUIRE(log.size() == 4);
	CHECK(log[0] == "P:enter");
	CHECK(log[1] == "C:enter");
	CHECK(log[2] == "C:ready");
	CHECK(log[3] == "P:ready");

	log.clear();
	tree->get_root()->remove_child(p);
	REQUIRE(log.size() == 2);
	CHECK(log[0] == "C:exit");
	CHECK(log[1] == "P:exit");
	CHECK_FALSE(p->is_inside_tree());
	delete p;
	delete tree;
}

TEST_CASE("[Node3D] defaults and transform set by name as the scene loader does") {
	DummyServer server;
	Node3D *n = new Node3D;
	CHECK(n->get_transform() == Transform3D());
	CHECK(n->is_visible());
	CHECK(n->get_scale().is_equal_approx(Vector3(1, 1, 1)));
	CHECK(n->get_rotation().is_equal_approx(Vector3()));

	Transform3D t(Basis::from_euler(Vector3(0.2f, 0.5f, -0.3f)).scaled(Vector3(2, 2, 2)), Vector3(1, 2, 3));
	bool valid = false;
	n->set("transform", t, &valid);
	CHECK(valid);
	CHECK(n->get_transform().is_equal_approx(t));
	CHECK(Vector3(n->get("position")).is_equal_approx(Vector3(1, 2, 3)));
	CHECK(Vector3(n->get("scale")).is_equal_approx(Vector3(2, 2, 2)));
	CHECK(Vector3(n->get("rotation")).is_equal_approx(Vector3(0.2f, 0.5f, -0.3f)));

	std::vector<PropertyInfo> list;
	n->get_property_list(&list);
	for (const PropertyInfo &p : list) {
		if (p.name == "transform") {
			CHECK_MESSAGE(p.usage == PROPERTY_USAGE_NO_EDITOR, "transform is saved (as Godot's .tscn) but edited through position/rotation/scale");
		}
		if (p.name == "position" || p.name == "rotation" || p.name == "scale") {
			CHECK_MESSAGE(!(p.usage & PROPERTY_USAGE_STORAGE), "position/rotation/scale are not saved separately");
		}
	}
	delete n;
}

TEST_CASE("[Node3D] rotation is YXZ Euler in radians and round-trips") {
	DummyServer server;
	Node3D *n = new Node3D;
	const Vector3 euler(0.3f, -1.2f, 0.7f);
	n->set_rotation(euler);
	CHECK(n->get_rotation() == euler);
	CHECK(n->get_transform().basis.is_equal_approx(Basis::from_euler(euler)));
	// YXZ: R = Ry * Rx * Rz.
	Basis expected = Basis::from_axis_angle(Vector3(0, 1, 0), euler.y) * Basis::from_axis_angle(Vector3(1, 0, 0), euler.x) * Basis::from_axis_angle(Vector3(0, 0, 1), euler.z);
	CHECK(n->get_transform().basis.is_equal_approx(expected));
	// Decomposing a basis set directly gives the same angles.
	CHECK(Node3D::basis_get_euler_yxz(expected).is_equal_approx(euler));
	n->set_rotation_degrees(Vector3(0, 90, 0));
	CHECK(n->get_transform().basis.xform(Vector3(0, 0, -1)).is_equal_approx(Vector3(-1, 0, 0)));
	// Scale survives a rotation change and the other way round.
	n->set_scale(Vector3(1, 2, 3));
	n->set_rotation(Vector3(0.1f, 0.2f, 0.3f));
	CHECK(n->get_scale().is_equal_approx(Vector3(1, 2, 3)));
	CHECK(n->get_transform().basis.get_scale().is_equal_approx(Vector3(1, 2, 3)));
	delete n;
}

TEST_CASE("[Node3D] global transform propagates to children and to the server") {
	DummyServer server;
	SceneTree *tree = new SceneTree;
	NotificationLog *parent = new NotificationLog;
	parent->set_transform(Transform3D(Basis::from_euler(Vector3(0, real_t(Math::PI / 2), 0)), Vector3(1, 2, 3)));
	MeshInstance3D *child = new MeshInstance3D;
	Ref<BoxMesh> box;
	box.instantiate();
	child->set_mesh(box);
	child->set_position(Vector3(1, 0, 0));
	// Cached globals of a subtree follow a new parent.
	Node3D *grandchild = new Node3D;
	grandchild->set_position(Vector3(0, 1, 0));
	child->add_child(grandchild);
	CHECK(grandchild->get_global_transform().origin.is_equal_approx(Vector3(1, 1, 0)));
	parent->add_child(child);
	CHECK(grandchild->get_global_transform().origin.is_equal_approx(Vector3(1, 3, 2)));

	// Outside the tree the math already works.
	CHECK(child->get_global_transform().origin.is_equal_approx(parent->get_transform().xform(Vector3(1, 0, 0))));
	CHECK(child->get_global_transform().origin.is_equal_approx(Vector3(1, 2, 2)));

	tree->get_root()->add_child(parent);
	AABB world = RS::get_singleton()->instance_get_aabb(child->get_instance());
	CHECK(world.get_center().is_equal_approx(Vector3(1, 2, 2)));

	int before = parent->transform_changes;
	parent->set_position(Vector3(-5, 0, 0));
	CHECK(parent->transform_changes == before + 1);
	CHECK(child->get_global_position().is_equal_approx(Vector3(-5, 0, -1)));
	world = RS::get_singleton()->instance_get_aabb(child->get_instance());
	CHECK_MESSAGE(world.get_center().is_equal_approx(Vector3(-5, 0, -1)), "moving the parent must update the child's instance on the server");

	child->set_global_position(Vector3(0, 0, 0));
	CHECK(child->get_global_position().is_equal_approx(Vector3(0, 0, 0)));
	CHECK(child->get_position().is_equal_approx(Vector3(0, 0, 5)));
	delete tree;
}

TEST_CASE("[Node3D] non-finite transforms are rejected and the old value kept") {
	DummyServer server;
	ErrorCatcher errors;
	Node3D *n = new Node3D;
	n->set_position(Vector3(1, 1, 1));
	n->set_position(Vector3(NAN, 0, 0));
	n->set_scale(Vector3(INFINITY, 1, 1));
	n->set("transform", Transform3D(Basis(), Vector3(0, NAN, 0)));
	CHECK(n->get_position() == Vector3(1, 1, 1));
	CHECK(n->get_scale().is_equal_approx(Vector3(1, 1, 1)));
	CHECK(errors.contains("finite"));
	delete n;
}

TEST_CASE("[Node3D] visibility is inherited") {
	DummyServer server;
	Node3D *parent = new Node3D;
	Node3D *child = new Node3D;
	parent->add_child(child);
	CHECK(child->is_visible_in_tree());
	parent->set("visible", false);
	CHECK(child->is_visible());
	CHECK_FALSE(child->is_visible_in_tree());
	parent->show();
	CHECK(child->is_visible_in_tree());
	delete parent;
}

TEST_CASE("[Camera3D] Godot defaults, current camera and projection") {
	DummyServer server;
	SceneTree *tree = new SceneTree;
	Camera3D *cam = new Camera3D;
	CHECK(cam->get_fov() == doctest::Approx(75.0));
	CHECK(cam->get_near() == doctest::Approx(0.05));
	CHECK(cam->get_far() == doctest::Approx(4000.0));
	CHECK(cam->get("keep_aspect").to_int() == Camera3D::KEEP_HEIGHT);
	CHECK(cam->get("projection").to_int() == Camera3D::PROJECTION_PERSPECTIVE);
	CHECK_FALSE(cam->is_current());

	tree->get_root()->add_child(cam);
	CHECK_MESSAGE(cam->is_current(), "the first camera to enter the tree becomes current");
	CHECK(tree->get_camera_3d() == cam);

	Camera3D *second = new Camera3D;
	second->set("current", true);
	tree->get_root()->add_child(second);
	CHECK(tree->get_camera_3d() == second);
	CHECK_FALSE(cam->is_current());

	// Projection: a point on the view axis maps to the centre; a point at the top edge of the
	// vertical fov maps to y = 1 (OpenGL clip convention).
	Projection p = cam->get_camera_projection(2.0f);
	const real_t half = Math::deg_to_rad(75.0f) * 0.5f;
	Vector3 top = p.xform(Vector3(0, std::tan(half) * 10, -10));
	CHECK(top.y == doctest::Approx(1.0).epsilon(1e-4));
	CHECK(top.x == doctest::Approx(0.0));

	cam->set_rotation(Vector3(0, real_t(Math::PI / 2), 0));
	Vector3 ray = cam->project_ray_normal(Vector2(32, 32), Vector2(64, 64));
	CHECK_MESSAGE(ray.is_equal_approx(Vector3(-1, 0, 0)), "the centre ray follows the camera's -Z");

	ErrorCatcher errors;
	cam->set("fov", 0.0);
	cam->set("near", -1.0);
	CHECK(cam->get_fov() == doctest::Approx(75.0));
	CHECK(cam->get_near() == doctest::Approx(0.05));
	CHECK(errors.contains("fov"));
	delete tree;
}

TEST_CASE("[MeshInstance3D] mesh, AABB and surface material override by property name") {
	DummyServer server;
	MeshInstance3D *mi = new MeshInstance3D;
	CHECK(mi->get_aabb().size == Vector3());
	Ref<SphereMesh> sphere;
	sphere.instantiate();
	mi->set("mesh", sphere);
	CHECK(mi->get_mesh() == sphere);
	// Rings do not sample the equator exactly, so the bound is slightly inside the ideal one.
	CHECK(mi->get_aabb().position.y == doctest::Approx(-0.5));
	CHECK(mi->get_aabb().size.x == doctest::Approx(1.0).epsilon(0.01));
	CHECK(mi->get_surface_override_material_count() == 1);

	Ref<StandardMaterial3D> mat;
	mat.instantiate();
	bool valid = false;
	mi->set("surface_material_override/0", mat, &valid);
	CHECK(valid);
	CHECK(mi->get_surface_override_material(0) == mat);
	CHECK(mi->get_active_material(0) == mat);
	CHECK(Ref<Material>(mi->get("surface_material_override/0")) == mat);
	delete mi;
}

TEST_CASE("[WorldEnvironment] puts its environment into the tree's world") {
	DummyServer server;
	SceneTree *tree = new SceneTree;
	WorldEnvironment *we = new WorldEnvironment;
	Ref<Environment> env;
	env.instantiate();
	env->set("background_mode", (int)Environment::BG_COLOR);
	env->set("background_color", Color(0.2f, 0.3f, 0.4f));
	CHECK(env->get_background() == Environment::BG_COLOR);
	CHECK(env->get_bg_color() == Color(0.2f, 0.3f, 0.4f));
	we->set_environment(env);
	CHECK(tree->get_world_3d()->get_environment().is_null());
	tree->get_root()->add_child(we);
	CHECK(tree->get_world_3d()->get_environment() == env);
	tree->get_root()->remove_child(we);
	CHECK(tree->get_world_3d()->get_environment().is_null());
	delete we;
	delete tree;
}

TEST_CASE("[SceneTree] a scene reaches the renderer: camera, visible geometry, lights, environment") {
	DummyServer server;
	SceneTree *tree = new SceneTree;
	Node3D *scene = new Node3D;

	Camera3D *cam = new Camera3D;
	cam->set_position(Vector3(0, 0, 5));
	cam->set_fov(60.0f);
	scene->add_child(cam);

	MeshInstance3D *box = new MeshInstance3D;
	Ref<BoxMesh> mesh;
	mesh.instantiate();
	box->set_mesh(mesh);
	Ref<StandardMaterial3D> mat;
	mat.instantiate();
	mat->set("albedo_color", Color(1, 0, 0));
	mat->set("roughness", 0.25);
	box->set("material_override", mat);
	scene->add_child(box);

	MeshInstance3D *hidden = new MeshInstance3D;
	hidden->set_mesh(mesh);
	hidden->set_visible(false);
	scene->add_child(hidden);

	OmniLight3D *omni = new OmniLight3D;
	omni->set_position(Vector3(0, 2, 0));
	scene->add_child(omni);
	DirectionalLight3D *sun = new DirectionalLight3D;
	scene->add_child(sun);
	DirectionalLight3D *editor_sun = new DirectionalLight3D;
	editor_sun->set("editor_only", true);
	scene->add_child(editor_sun);

	WorldEnvironment *we = new WorldEnvironment;
	Ref<Environment> env;
	env.instantiate();
	env->set("background_mode", (int)Environment::BG_COLOR);
	env->set("background_color", Color(0, 0, 1));
	we->set_environment(env);
	scene->add_child(we);

	tree->get_root()->add_child(scene);
	tree->set_size(64, 32);
	tree->render();

	const RenderSceneData &d = server.last_scene();
	CHECK(d.viewport_width == 64);
	CHECK(d.fovy_degrees == doctest::Approx(60.0));
	CHECK(d.cam_transform.origin.is_equal_approx(Vector3(0, 0, 5)));
	REQUIRE_MESSAGE(d.geometry.size() == 1, "the hidden mesh instance is not drawn");
	CHECK(d.geometry[0].material_override == mat->get_rid());
	CHECK(d.geometry[0].mesh == mesh->get_rid());
	CHECK(d.lights.size() == 1);
	CHECK_MESSAGE(d.directional_lights.size() == 1, "editor_only lights are not drawn outside the editor");
	CHECK(d.environment.has_environment);
	CHECK(d.environment.background == RS::ENV_BG_COLOR);
	CHECK(d.environment.bg_color == Color(0, 0, 1));
	RS::MaterialParams params = RS::get_singleton()->material_get_params(mat->get_rid());
	CHECK(params.albedo == Color(1, 0, 0));
	CHECK(params.roughness == doctest::Approx(0.25));

	// Showing the hidden instance and moving the camera are picked up on the next draw.
	hidden->show();
	cam->set_position(Vector3(0, 1, 6));
	tree->render();
	CHECK(server.last_scene().geometry.size() == 2);
	CHECK(server.last_scene().cam_transform.origin.is_equal_approx(Vector3(0, 1, 6)));
	delete tree;
}

TEST_CASE("[Node3D] rotate, translate, to_global/to_local as Godot's helpers") {
	DummyServer server;
	ErrorCatcher errors;
	Node3D *parent = new Node3D;
	parent->set_position(Vector3(10, 0, 0));
	Node3D *node = new Node3D;
	parent->add_child(node);
	node->rotate_y(real_t(Math::PI / 2));
	CHECK(node->get_rotation().is_equal_approx(Vector3(0, real_t(Math::PI / 2), 0)));
	// translate() moves along the node's own axes: local -Z is world -X after the turn.
	node->translate(Vector3(0, 0, -1));
	CHECK(node->get_position().is_equal_approx(Vector3(-1, 0, 0)));
	node->global_translate(Vector3(0, 2, 0));
	CHECK(node->get_global_position().is_equal_approx(Vector3(9, 2, 0)));
	CHECK(node->to_global(Vector3(0, 0, -1)).is_equal_approx(Vector3(8, 2, 0)));
	CHECK(node->to_local(Vector3(8, 2, 0)).is_equal_approx(Vector3(0, 0, -1)));
	// About its own X axis: local +Y turns to local +Z, which is parent +X after the turn.
	node->rotate_object_local(Vector3(1, 0, 0), real_t(Math::PI / 2));
	CHECK(node->get_transform().basis.xform(Vector3(0, 1, 0)).is_equal_approx(Vector3(1, 0, 0)));
	CHECK(errors.messages.size() == 0);
	node->rotate(Vector3(), 1); // A zero axis is an error, the transform is kept.
	CHECK(errors.messages.size() == 1);
	delete parent;
}

TEST_CASE("[Node] groups, duplicate and queue_free") {
	DummyServer server;
	ErrorCatcher errors;
	Node3D *node = new Node3D;
	node->set_name("Lamp");
	node->set_position(Vector3(1, 2, 3));
	node->add_to_group("lights");
	node->add_to_group("lights"); // Once only.
	CHECK(node->is_in_group("lights"));
	CHECK(node->get_groups().size() == 1);
	Node3D *child = new Node3D;
	child->set_name("Child");
	node->add_child(child);

	Node *copy = node->duplicate();
	REQUIRE(copy != nullptr);
	CHECK(copy->get_class() == "Node3D");
	CHECK(copy->get_name() == "Lamp");
	CHECK(static_cast<Node3D *>(copy)->get_position().is_equal_approx(Vector3(1, 2, 3)));
	CHECK(copy->is_in_group("lights"));
	REQUIRE(copy->get_child_count() == 1);
	CHECK(copy->get_child(0) != child);
	CHECK(copy->get_child(0)->get_name() == "Child");

	node->remove_from_group("lights");
	CHECK(!node->is_in_group("lights"));
	CHECK(errors.messages.size() == 0);
	node->remove_from_group("lights");
	CHECK(errors.messages.size() == 1);

	// queue_free(): deleted at the next flush (SceneTree runs it before drawing), not at once;
	// a queued node deleted by its parent first leaves the queue.
	static std::vector<Node *> deleted;
	deleted.clear();
	Node::predelete_callback = [](Node *p_node) { deleted.push_back(p_node); };
	copy->get_child(0)->queue_free();
	copy->queue_free();
	CHECK(copy->is_queued_for_deletion());
	CHECK(deleted.empty());
	Node::flush_delete_queue();
	CHECK(deleted.size() == 2);
	Node::flush_delete_queue(); // Nothing left.
	CHECK(deleted.size() == 2);
	Node::predelete_callback = nullptr;
	delete node;
}

} // namespace TestNode3D
