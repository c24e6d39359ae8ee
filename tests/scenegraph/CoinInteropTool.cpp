// coin_interop_tool: the Coin3D side of the interop tests (CoinInteropTest.cpp). Linked against
// Coin only, so what it reads and writes is what a real Open Inventor program does.
//
//   coin_interop_tool rewrite IN OUT   read IN with SoDB::readAll, write it to OUT (SoWriteAction)
//   coin_interop_tool describe IN      print the graph: one line per node (its file-format type
//                                      name and name), then its non-default fields
//   coin_interop_tool sample OUT       write a scene built with Coin's API
// Exit code 0 on success, 1 when Coin cannot read or write (Coin prints why on stderr).

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoOutput.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/fields/SoField.h>
#include <Inventor/fields/SoFieldData.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSwitch.h>

#include <cstdio>
#include <cstring>
#include <string>

// In sanitizer builds: Coin allocates its type system and field tables in SoDB::init() and
// keeps them until exit by design; those are not leaks of this test.
extern "C" const char* __lsan_default_suppressions() { return "leak:libCoin.so\n"; }

namespace {

SoSeparator* readScene(const char* path) {
    SoInput input;
    if (!input.openFile(path)) {
        return nullptr;
    }
    return SoDB::readAll(&input);
}

bool writeScene(SoNode* root, const char* path) {
    SoOutput output;
    if (!output.openFile(path)) {
        return false;
    }
    SoWriteAction(&output).apply(root);
    output.closeFile();
    return true;
}

// The name a node has in files: the class name for built-ins, the file's name for nodes Coin
// read as unknown. Coin keeps getFileFormatName() protected; a member pointer named through a
// derived class reaches it.
struct FileFormatName : SoNode {
    static const char* of(const SoNode* node) {
        return (node->*(&FileFormatName::getFileFormatName))();
    }
};

void describe(SoNode* node, int depth) {
    const std::string indent(static_cast<std::size_t>(depth) * 2, ' ');
    std::printf("%s%s", indent.c_str(), FileFormatName::of(node));
    if (node->getName().getLength() > 0) {
        std::printf(" \"%s\"", node->getName().getString());
    }
    std::printf("\n");
    SoFieldList fields;
    node->getFields(fields);
    for (int i = 0; i < fields.getLength(); ++i) {
        SoField* field = fields[i];
        SbName name;
        node->getFieldName(field, name);
        if (field->isConnected()) {
            std::printf("%s  %s connected\n", indent.c_str(), name.getString());
        } else if (!field->isDefault()) {
            SbString value;
            field->get(value);
            std::printf("%s  %s %s\n", indent.c_str(), name.getString(), value.getString());
        }
    }
    if (SoChildList* children = node->getChildren()) {
        for (int i = 0; i < children->getLength(); ++i) {
            describe((*children)[i], depth + 1);
        }
    }
}

// Standard nodes only (the core's types), with the sharing and naming cases of the format:
// a shared unnamed node (Coin writes DEF +0), a named node used twice, and a field connection.
SoSeparator* makeSample() {
    auto* root = new SoSeparator;
    root->ref();
    auto* shared = new SoGroup;
    auto* chooser = new SoSwitch;
    chooser->setName("chooser");
    chooser->whichChild.setValue(1);
    chooser->addChild(shared);
    chooser->addChild(new SoSeparator);
    auto* follower = new SoSwitch;
    follower->whichChild.connectFrom(&chooser->whichChild);
    root->addChild(chooser);
    root->addChild(shared);
    root->addChild(follower);
    root->addChild(chooser);
    return root;
}

} // namespace

int main(int argc, char** argv) {
    SoDB::init();
    const std::string command = argc > 1 ? argv[1] : "";
    if (command == "rewrite" && argc == 4) {
        SoSeparator* root = readScene(argv[2]);
        return root != nullptr && writeScene(root, argv[3]) ? 0 : 1;
    }
    if (command == "describe" && argc == 3) {
        SoSeparator* root = readScene(argv[2]);
        if (root == nullptr) {
            return 1;
        }
        describe(root, 0);
        return 0;
    }
    if (command == "sample" && argc == 3) {
        return writeScene(makeSample(), argv[2]) ? 0 : 1;
    }
    std::fprintf(stderr, "usage: coin_interop_tool rewrite IN OUT | describe IN | sample OUT\n");
    return 2;
}
