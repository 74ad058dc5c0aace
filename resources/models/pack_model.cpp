// pack_model MODEL PACK: the compact form of a model (common/gltf/model_pack.h) for the pages,
// which have no Assimp: MODEL loaded by the native loader (pbr::loadModel), written to PACK with
// its texture files inside. The build packs the project's three models this way.
#include <cstdio>

#include "base/error.h"
#include "gltf/model.h"
#include "gltf/model_pack.h"

int main(int argc, char** argv) try {
    if (argc != 3) throw pbr::Error("usage: pack_model MODEL PACK");
    pbr::writeModelPack(pbr::loadModel(argv[1]), argv[2]);
    return 0;
} catch (...) {
    return pbr::reportFailure();
}
