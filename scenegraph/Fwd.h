#pragma once

/// @file
/// @brief Forward declarations of the scene-graph core (namespace texsplat::sg).

#include <memory>

namespace texsplat::sg {

class Action;
class BoundingBoxAction;
class Box3;
class Engine;
class EngineOutputBase;
class EnumNames;
class Field;
class FieldContainer;
class FieldValueReader;
class FieldValueWriter;
class Group;
class MethodTable;
class MFNode;
class Node;
class NodeRegistry;
class NodeType;
class Notifier;
class Observer;
class Path;
class Rotation;
class SearchAction;
class Separator;
class SFEnum;
class SFNode;
class State;
class Switch;

} // namespace texsplat::sg
