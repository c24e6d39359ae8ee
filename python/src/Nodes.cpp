#include "Bindings.h"

#include "nodes/VolumeData.h"
#include "scenegraph/Error.h"
#include "scenegraph/Group.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/NodeType.h"

#include <nanobind/stl/optional.h>
#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <optional>
#include <string>
#include <vector>

namespace texsplat::python {
namespace {

sg::Field& fieldNamed(const sg::Node& node, const std::string& name) {
    sg::Field* field = node.findField(name);
    if (field == nullptr) {
        std::string names;
        for (const sg::Field* each : node.fields()) {
            names += (names.empty() ? "" : ", ") + each->name();
        }
        throw nb::attribute_error((node.describe() + " has no field '" + name + "'" +
                                   (names.empty() ? "" : "; its fields: " + names))
                                      .c_str());
    }
    return *field;
}

sg::Group& asGroup(sg::Node& node) {
    auto* group = dynamic_cast<sg::Group*>(&node);
    if (group == nullptr) {
        throw nb::type_error((node.describe() + " is not a group: it has no children").c_str());
    }
    return *group;
}

sg::Node::Ptr createNode(const std::string& typeName, const nb::kwargs& fields) {
    const sg::NodeType* type = sg::NodeRegistry::instance().find(typeName);
    if (type == nullptr || !type->isDerivedFrom(sg::Node::classType())) {
        throw DataError("unknown node type '" + typeName + "'; texsplat.node_types() lists them");
    }
    sg::FieldContainer::Ptr container = type->create();
    sg::Node::Ptr node = std::static_pointer_cast<sg::Node>(container);
    for (auto [name, value] : fields) {
        setFieldValue(fieldNamed(*node, nb::cast<std::string>(name)), value);
    }
    return node;
}

std::vector<std::string> nodeTypeNames() {
    std::vector<std::string> names;
    for (const sg::NodeType* type : sg::NodeRegistry::instance().types()) {
        if (!type->isAbstract() && type->isDerivedFrom(sg::Node::classType())) {
            names.push_back(type->name());
        }
    }
    return names;
}

glm::dvec3 vectorOr(const std::optional<std::vector<double>>& values, double fallback,
                    const char* name) {
    if (!values) {
        return glm::dvec3(fallback);
    }
    if (values->size() != 3) {
        throw DataError(std::string(name) + ": expected 3 numbers (x, y, z), got " +
                        std::to_string(values->size()));
    }
    return {(*values)[0], (*values)[1], (*values)[2]};
}

void setArray(sg::Node& node, nb::handle array, const std::optional<std::vector<double>>& spacing,
              const std::optional<std::vector<double>>& origin,
              const std::optional<std::string>& name) {
    auto* data = dynamic_cast<nodes::VolumeData*>(&node);
    if (data == nullptr) {
        throw nb::type_error((node.describe() + " is not a VolumeData").c_str());
    }
    const std::string source = name ? *name : node.name().empty() ? "array" : node.describe();
    data->setGrid(gridFromPython(array, source, vectorOr(origin, 0.0, "origin"),
                                 vectorOr(spacing, 1.0, "spacing")));
}

} // namespace

void bindNodes(nb::module_& module) {
    nb::class_<sg::Node>(module, "Node",
                         "A node of a scene: its fields (by name, as attributes), its children "
                         "(groups), its DEF name.")
        .def(nb::new_(&createNode), nb::arg("type_name"), nb::arg("fields"),
             "A new node of the type named `type_name` (node_types()), its fields set from the "
             "keyword arguments.")
        .def_prop_ro("type_name", [](const sg::Node& node) { return node.typeName(); },
                     "The scene-file type name (\"TransferFunction\").")
        .def_prop_rw(
            "name", [](const sg::Node& node) { return node.name(); },
            [](sg::Node& node, std::string name) { node.setName(std::move(name)); },
            "The DEF name (\"\" when it has none).")
        .def_prop_ro(
            "fields",
            [](const sg::Node& node) {
                nb::dict types;
                for (const sg::Field* field : node.fields()) {
                    types[field->name().c_str()] = std::string(field->typeName());
                }
                return types;
            },
            "The fields' names and Inventor types, in declaration order.")
        .def(
            "field_description",
            [](const sg::Node& node, const std::string& name) {
                fieldNamed(node, name);
                return node.type().fieldDescription(name);
            },
            nb::arg("name"), "What the field means (its unit and range).")
        .def(
            "__getattr__",
            [](const sg::Node& node, const std::string& name) {
                return fieldValue(fieldNamed(node, name));
            },
            nb::arg("name"))
        .def(
            "__setattr__",
            [](sg::Node& node, const std::string& name, nb::handle value) {
                if (name == "name") {
                    node.setName(nb::cast<std::string>(value));
                    return;
                }
                setFieldValue(fieldNamed(node, name), value);
            },
            nb::arg("name"), nb::arg("value"))
        .def("__dir__",
             [](nb::handle self) {
                 nb::list names = nb::borrow<nb::list>(
                     nb::module_::import_("builtins").attr("object").attr("__dir__")(self));
                 for (const sg::Field* field : nb::cast<sg::Node&>(self).fields()) {
                     names.append(nb::str(field->name().c_str()));
                 }
                 return names;
             })
        .def("__repr__",
             [](const sg::Node& node) { return "<texsplat.Node " + node.describe() + ">"; })
        .def_prop_ro(
            "children",
            [](sg::Node& node) { return asGroup(node).children(); },
            "The children of a group (Separator, Group, Switch), in order.")
        .def(
            "add_child", [](sg::Node& node, sg::Node::Ptr child) {
                asGroup(node).addChild(std::move(child));
            },
            nb::arg("child"), "Appends `child` to a group's children.")
        .def(
            "insert_child",
            [](sg::Node& node, std::size_t index, sg::Node::Ptr child) {
                asGroup(node).insertChild(std::move(child), index);
            },
            nb::arg("index"), nb::arg("child"), "Inserts `child` before child `index`.")
        .def(
            "remove_child",
            [](sg::Node& node, std::size_t index) { asGroup(node).removeChild(index); },
            nb::arg("index"), "Removes child `index` of a group.")
        .def("set_array", &setArray, nb::arg("array"), nb::arg("spacing").none() = nb::none(),
             nb::arg("origin").none() = nb::none(), nb::kw_only(),
             nb::arg("name").none() = nb::none(),
             "Draws a NumPy array (z, y, x) or (z, y, x, 3) in this VolumeData, in place of its "
             "file: a C-contiguous float32 array without a copy (keep it unchanged while the "
             "node holds it), any other converted once. `spacing` and `origin` (x, y, z) place "
             "the voxels. Its `source` becomes MEMORY. Messages name the array `name` (default: the "
             "node).");
    module.def("node_types", &nodeTypeNames,
               "The names of the node types a scene can hold (the registry's).");
}

} // namespace texsplat::python
