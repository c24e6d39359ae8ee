// coin_interop_tool: the Coin3D side of the interop tests (CoinInteropTest.cpp). Linked against
// Coin only, so what it reads and writes is what a real Open Inventor program does.
//
//   coin_interop_tool rewrite IN OUT    read IN with SoDB::readAll, write it to OUT (SoWriteAction)
//   coin_interop_tool describe IN       print the graph: one line per node (its file-format type
//                                       name and name), then its non-default fields; a connected
//                                       field as `name = Type . source`, an engine's fields below
//   coin_interop_tool sample OUT        write a scene of core nodes built with Coin's API
//   coin_interop_tool standard OUT      write the standard nodes texsplat has, every field set
//   coin_interop_tool fields TYPE...    print each type's fields (type, name, default) and outputs
// Exit code 0 on success, 1 when Coin cannot read or write (Coin prints why on stderr).

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoOutput.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/engines/SoElapsedTime.h>
#include <Inventor/engines/SoEngineOutput.h>
#include <Inventor/engines/SoOutputData.h>
#include <Inventor/fields/SoField.h>
#include <Inventor/fields/SoFieldData.h>
#include <Inventor/fields/SoSFTrigger.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSwitch.h>
#include <Inventor/nodes/SoTransform.h>

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

// The name a node or engine has in files: the class name for built-ins, the file's name for
// nodes Coin read as unknown. Coin keeps getFileFormatName() protected; a member pointer named
// through a derived class reaches it.
struct FileFormatName : SoFieldContainer {
    static const char* of(const SoFieldContainer* container) {
        return (container->*(&FileFormatName::getFileFormatName))();
    }
};

// A field's value as one line: Coin breaks long lists into lines and puts two spaces before a
// rotation's angle; whitespace runs become one space.
std::string valueText(SoField* field) {
    SbString value;
    field->get(value);
    std::string text;
    for (const char* c = value.getString(); *c != '\0'; ++c) {
        const bool isSpace = *c == ' ' || *c == '\n' || *c == '\t';
        if (!isSpace) {
            text += *c;
        } else if (!text.empty() && text.back() != ' ') {
            text += ' ';
        }
    }
    while (!text.empty() && text.back() == ' ') {
        text.pop_back();
    }
    return text;
}

// True for a connection from Coin's global clock (realTime), which SoElapsedTime makes itself.
bool isFromGlobalField(const SoField& field) {
    SoField* master = nullptr;
    return field.getConnectedField(master) && master->getContainer() != nullptr &&
           master->getContainer()->getTypeId().getName() == SbName("GlobalField");
}

void describeFields(SoFieldContainer* container, int depth);

void describeField(SoFieldContainer* container, SoField* field, int depth) {
    const std::string indent(static_cast<std::size_t>(depth) * 2, ' ');
    SbName name;
    container->getFieldName(field, name);
    SoEngineOutput* output = nullptr;
    SoField* master = nullptr;
    if (isFromGlobalField(*field) || field->isOfType(SoSFTrigger::getClassTypeId())) {
        // The clock's reading and triggers carry no value a file keeps.
        return;
    }
    if (field->getConnectedEngine(output)) {
        SoEngine* engine = output->getContainer();
        SbName outputName;
        engine->getOutputName(output, outputName);
        std::printf("%s%s = %s . %s\n", indent.c_str(), name.getString(),
                    FileFormatName::of(engine), outputName.getString());
        describeFields(engine, depth + 2);
    } else if (field->getConnectedField(master)) {
        SbName masterName;
        master->getContainer()->getFieldName(master, masterName);
        std::printf("%s%s = %s . %s\n", indent.c_str(), name.getString(),
                    FileFormatName::of(master->getContainer()), masterName.getString());
    } else if (!field->isDefault()) {
        std::printf("%s%s %s\n", indent.c_str(), name.getString(), valueText(field).c_str());
    }
}

void describeFields(SoFieldContainer* container, int depth) {
    SoFieldList fields;
    container->getFields(fields);
    for (int i = 0; i < fields.getLength(); ++i) {
        describeField(container, fields[i], depth);
    }
}

void describe(SoNode* node, int depth) {
    const std::string indent(static_cast<std::size_t>(depth) * 2, ' ');
    std::printf("%s%s", indent.c_str(), FileFormatName::of(node));
    if (node->getName().getLength() > 0) {
        std::printf(" \"%s\"", node->getName().getString());
    }
    std::printf("\n");
    describeFields(node, depth + 1);
    if (SoChildList* children = node->getChildren()) {
        for (int i = 0; i < children->getLength(); ++i) {
            describe((*children)[i], depth + 1);
        }
    }
}

// One line per field, `  TYPE NAME DEFAULT` (`connected` for a default that follows another
// field, as ElapsedTime's timeIn follows the clock), then `  output TYPE NAME` per engine output.
// A type Coin does not know prints `TYPE unknown`.
void printFields(const char* typeName) {
    const SoType type = SoType::fromName(typeName);
    if (type.isBad() || !type.canCreateInstance() ||
        !type.isDerivedFrom(SoFieldContainer::getClassTypeId())) {
        std::printf("%s unknown\n", typeName);
        return;
    }
    auto* container = static_cast<SoFieldContainer*>(type.createInstance());
    container->ref();
    std::printf("%s\n", typeName);
    const SoFieldData* data = container->getFieldData();
    for (int i = 0; data != nullptr && i < data->getNumFields(); ++i) {
        SoField* field = data->getField(container, i);
        const std::string value = field->isConnected() ? "connected" : valueText(field);
        std::printf("  %s %s %s\n", field->getTypeId().getName().getString(),
                    data->getFieldName(i).getString(), value.c_str());
    }
    if (container->isOfType(SoEngine::getClassTypeId())) {
        const SoEngineOutputData* outputs = static_cast<SoEngine*>(container)->getOutputData();
        for (int i = 0; i < outputs->getNumOutputs(); ++i) {
            const SoEngineOutput* output =
                outputs->getOutput(static_cast<SoEngine*>(container), i);
            std::printf("  output %s %s\n", output->getConnectionType().getName().getString(),
                        outputs->getOutputName(i).getString());
        }
    }
    container->unref();
}

// Standard nodes only (the core's types), with the sharing and naming cases of the format:
// a shared unnamed node (Coin writes DEF +0), a named node used twice, and a field connection;
// the root has some of its caching fields set.
SoSeparator* makeSample() {
    auto* root = new SoSeparator;
    root->ref();
    root->renderCaching = SoSeparator::OFF;
    root->pickCulling = SoSeparator::ON;
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

// The standard nodes texsplat has, every field Coin writes set to a value that is not its
// default, multi-valued fields with several values, and an ElapsedTime (every input set, the
// reset trigger fired) driving a light.
SoSeparator* makeStandardSample() {
    auto* root = new SoSeparator;
    root->ref();
    root->renderCaching = SoSeparator::OFF;
    root->boundingBoxCaching = SoSeparator::ON;
    root->renderCulling = SoSeparator::OFF;
    root->pickCulling = SoSeparator::ON;

    auto* perspective = new SoPerspectiveCamera;
    perspective->viewportMapping = SoCamera::LEAVE_ALONE;
    perspective->position.setValue(1.0f, 2.0f, 3.0f);
    perspective->orientation.setValue(SbVec3f(0.0f, 1.0f, 0.0f), 0.5f);
    perspective->nearDistance = 0.5f;
    perspective->farDistance = 50.0f;
    perspective->aspectRatio = 1.5f;
    perspective->focalDistance = 7.0f;
    perspective->heightAngle = 0.25f;
    root->addChild(perspective);

    auto* orthographic = new SoOrthographicCamera;
    orthographic->viewportMapping = SoCamera::CROP_VIEWPORT_NO_FRAME;
    orthographic->position.setValue(-1.0f, 0.0f, 4.0f);
    orthographic->orientation.setValue(SbVec3f(1.0f, 0.0f, 0.0f), -0.25f);
    orthographic->nearDistance = -2.0f;
    orthographic->farDistance = 8.0f;
    orthographic->aspectRatio = 0.75f;
    orthographic->focalDistance = 3.0f;
    orthographic->height = 6.0f;
    root->addChild(orthographic);

    auto* transform = new SoTransform;
    transform->translation.setValue(1.0f, -2.0f, 3.5f);
    transform->rotation.setValue(SbVec3f(0.0f, 0.0f, 1.0f), 1.5f);
    transform->scaleFactor.setValue(2.0f, 0.5f, 4.0f);
    transform->scaleOrientation.setValue(SbVec3f(0.0f, 1.0f, 0.0f), 0.125f);
    transform->center.setValue(0.25f, 0.5f, 0.75f);
    root->addChild(transform);

    auto* material = new SoMaterial;
    const SbColor ambient[] = {SbColor(0.1f, 0.2f, 0.3f), SbColor(0.4f, 0.5f, 0.6f)};
    const SbColor diffuse[] = {SbColor(1.0f, 0.0f, 0.0f), SbColor(0.0f, 1.0f, 0.0f),
                               SbColor(0.0f, 0.0f, 1.0f)};
    const SbColor specular[] = {SbColor(0.5f, 0.5f, 0.5f), SbColor(1.0f, 1.0f, 1.0f)};
    const SbColor emissive[] = {SbColor(0.0f, 0.25f, 0.0f), SbColor(0.0f, 0.0f, 0.25f)};
    const float shininess[] = {0.125f, 0.875f};
    const float transparency[] = {0.25f, 0.5f, 0.75f};
    material->ambientColor.setValues(0, 2, ambient);
    material->diffuseColor.setValues(0, 3, diffuse);
    material->specularColor.setValues(0, 2, specular);
    material->emissiveColor.setValues(0, 2, emissive);
    material->shininess.setValues(0, 2, shininess);
    material->transparency.setValues(0, 3, transparency);
    root->addChild(material);

    auto* light = new SoDirectionalLight;
    light->on = FALSE;
    light->color.setValue(1.0f, 0.5f, 0.25f);
    light->direction.setValue(0.0f, -1.0f, 0.0f);
    auto* time = new SoElapsedTime;
    time->speed = 2.0f;
    time->on = FALSE;
    time->pause = TRUE;
    time->reset.touch();
    light->intensity.connectFrom(&time->timeOut);
    root->addChild(light);

    auto* coordinates = new SoCoordinate3;
    const SbVec3f points[] = {SbVec3f(0.0f, 0.0f, 0.0f), SbVec3f(1.0f, 0.0f, 0.0f),
                              SbVec3f(1.0f, 1.0f, 0.0f), SbVec3f(0.0f, 1.0f, 0.0f)};
    coordinates->point.setValues(0, 4, points);
    root->addChild(coordinates);

    auto* faces = new SoIndexedFaceSet;
    const int32_t coordIndex[] = {0, 1, 2, -1, 0, 2, 3, -1};
    const int32_t materialIndex[] = {0, 1};
    const int32_t normalIndex[] = {0, 0, 0, -1, 1, 1, 1, -1};
    const int32_t textureCoordIndex[] = {3, 2, 1, -1};
    faces->coordIndex.setValues(0, 8, coordIndex);
    faces->materialIndex.setValues(0, 2, materialIndex);
    faces->normalIndex.setValues(0, 8, normalIndex);
    faces->textureCoordIndex.setValues(0, 4, textureCoordIndex);
    root->addChild(faces);
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
    if (command == "standard" && argc == 3) {
        return writeScene(makeStandardSample(), argv[2]) ? 0 : 1;
    }
    if (command == "fields" && argc >= 3) {
        for (int i = 2; i < argc; ++i) {
            printFields(argv[i]);
        }
        return 0;
    }
    std::fprintf(stderr, "usage: coin_interop_tool rewrite IN OUT | describe IN | sample OUT | "
                         "standard OUT | fields TYPE...\n");
    return 2;
}
