// The media modes, registered in one table: their names reach the command line, a scene's
// render.mode, `sandbox settings`, the schema, the editor and the error texts from here alone.
#include "nimbus/media/technique.h"

#include "billboards/billboards_technique.h"
#include "blocks/blocks_technique.h"
#include "particles/particles_technique.h"
#include "raymarch/raymarch_technique.h"
#include "sheets/sheets_technique.h"

namespace nimbus::media {

TechniqueTable builtInTechniques() {
    TechniqueTable table;
    table.add(particlesTechnique());
    table.add(blocksTechnique());
    table.add(raymarchTechnique());
    table.add(sheetsTechnique());
    table.add(billboardsTechnique());
    return table;
}

}  // namespace nimbus::media
