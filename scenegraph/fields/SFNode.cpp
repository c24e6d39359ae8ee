#include "scenegraph/fields/SFNode.h"

#include "scenegraph/Node.h"
#include "scenegraph/fields/FieldValueReader.h"
#include "scenegraph/fields/FieldValueWriter.h"

namespace texsplat::sg {

SFNode::~SFNode() {
    if (mValue && container() != nullptr) {
        mValue->removeParent(*container());
    }
}

void SFNode::setValue(std::shared_ptr<Node> node) {
    if (node != mValue && container() != nullptr) {
        if (node) {
            Node::checkNoCycle(*container(), *node, "the value of SFNode " + fullName());
            node->addParent(*container());
        }
        if (mValue) {
            mValue->removeParent(*container());
        }
    }
    mValue = std::move(node);
    valueChanged();
}

void SFNode::readValue(FieldValueReader& reader) { setValue(reader.readNode()); }

void SFNode::writeValue(FieldValueWriter& writer) const { writer.writeNode(mValue); }

void SFNode::copyValueFrom(const Field& other) {
    checkSameType(other);
    setValue(static_cast<const SFNode&>(other).mValue);
}

void SFNode::attached() {
    if (mValue) {
        mValue->addParent(*container());
    }
}

} // namespace texsplat::sg
