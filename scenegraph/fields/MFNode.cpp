#include "scenegraph/fields/MFNode.h"

#include "scenegraph/Node.h"
#include "scenegraph/fields/FieldValueReader.h"
#include "scenegraph/fields/FieldValueWriter.h"

namespace texsplat::sg {

MFNode::~MFNode() { unlink(mValues); }

void MFNode::setValue(std::vector<std::shared_ptr<Node>> nodes) {
    check(nodes);
    link(nodes);
    unlink(mValues);
    mValues = std::move(nodes);
    valueChanged();
}

void MFNode::set1Value(std::size_t index, std::shared_ptr<Node> node) {
    std::vector<std::shared_ptr<Node>> added{node};
    check(added);
    link(added);
    if (index >= mValues.size()) {
        mValues.resize(index + 1);
    }
    unlink({mValues[index]});
    mValues[index] = std::move(node);
    valueChanged();
}

void MFNode::readValue(FieldValueReader& reader) {
    std::vector<std::shared_ptr<Node>> nodes;
    if (reader.readChar('[')) {
        while (!reader.readChar(']')) {
            nodes.push_back(reader.readNode());
            reader.readChar(',');
        }
    } else {
        nodes.push_back(reader.readNode());
    }
    setValue(std::move(nodes));
}

void MFNode::writeValue(FieldValueWriter& writer) const {
    if (mValues.size() == 1) {
        writer.writeNode(mValues.front());
        return;
    }
    writer.beginList();
    for (const std::shared_ptr<Node>& node : mValues) {
        writer.writeNode(node);
    }
    writer.endList();
}

void MFNode::copyValueFrom(const Field& other) {
    checkSameType(other);
    setValue(static_cast<const MFNode&>(other).mValues);
}

void MFNode::attached() { link(mValues); }

void MFNode::check(const std::vector<std::shared_ptr<Node>>& nodes) const {
    if (container() == nullptr) {
        return;
    }
    for (const std::shared_ptr<Node>& node : nodes) {
        if (node) {
            Node::checkNoCycle(*container(), *node, "a value of MFNode " + fullName());
        }
    }
}

void MFNode::link(const std::vector<std::shared_ptr<Node>>& nodes) {
    if (container() == nullptr) {
        return;
    }
    for (const std::shared_ptr<Node>& node : nodes) {
        if (node) {
            node->addParent(*container());
        }
    }
}

void MFNode::unlink(const std::vector<std::shared_ptr<Node>>& nodes) {
    if (container() == nullptr) {
        return;
    }
    for (const std::shared_ptr<Node>& node : nodes) {
        if (node) {
            node->removeParent(*container());
        }
    }
}

} // namespace texsplat::sg
