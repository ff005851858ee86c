// Converts between the document model and the SDK's plain-C document view (sdk document.h),
// the form in which documents cross the plugin boundary.
#pragma once

#include "document/document.hpp"

#include <animator/document.h>
#include <animator/huge_pages.hpp>

#include <string>
#include <vector>

namespace animator {

// An ani_document_view of a Document, with the storage it points into. The document must
// outlive it and stay unchanged while the view is used.
class DocumentView {
  public:
    explicit DocumentView(const Document &doc);
    DocumentView(const DocumentView &) = delete;
    DocumentView &operator=(const DocumentView &) = delete;
    const ani_document_view &view() const { return view_; }

  private:
    ani::HugeVector<ani_model_desc> models_; // (at 100,000 models, 36 MB: huge_pages.hpp)
    std::vector<ani::HugeVector<ani_model_state>> states_; // per keyframe, a state per model
    std::vector<std::vector<int32_t>> keyed_;
    std::vector<ani_keyframe_view> keyframes_;
    std::vector<ani_param_setting> params_;
    std::vector<ani_light> lights_;
    ani_document_view view_{};
};

// Builds a Document from a view, checking every invariant. Throws DocumentError naming what is
// wrong ("model 'ball': mass must be a finite number > 0").
Document document_from_view(const ani_document_view &view);

ani_vec3 to_ani(const glm::dvec3 &v);
glm::dvec3 from_ani(const ani_vec3 &v);

} // namespace animator
